#include "StressStrain.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace plastic
{
namespace
{
std::string pairText(size_t index, const StressStrainPair& p)
{
	std::ostringstream text;
	text << "stress-strain pair " << index + 1 << " (" << p.strain << ", " << p.stress_pa << " Pa): ";
	return text.str();
}
}  // namespace

std::vector<std::string> validate(const StressStrainCurve& curve)
{
	std::vector<std::string> errors;
	if (curve.pairs.empty())
	{
		errors.push_back("stress-strain curve: no pairs (at least one (strain, stress) pair, strain > 0)");
		return errors;
	}
	for (size_t i = 0; i < curve.pairs.size(); i++)
	{
		const StressStrainPair& p = curve.pairs[i];
		const StressStrainPair before = i > 0 ? curve.pairs[i - 1] : StressStrainPair{};
		if (!std::isfinite(p.strain) || !std::isfinite(p.stress_pa))
			errors.push_back(pairText(i, p) + "not finite");
		else if (!(p.strain > before.strain))
			errors.push_back(pairText(i, p) + "strain not above the pair before's (" + std::to_string(before.strain) + ")");
		else if (!(p.stress_pa > 0))
			errors.push_back(pairText(i, p) + "stress not above 0");
		else if (p.stress_pa < before.stress_pa)
			errors.push_back(pairText(i, p) + "stress below the pair before's (the curve must not fall)");
		else if (i > 0 && (p.stress_pa - before.stress_pa) / (p.strain - before.strain) > curve.pairs[0].stress_pa / curve.pairs[0].strain)
			errors.push_back(pairText(i, p) + "steeper than the first pair's Young's modulus (yielding starts at the first pair)");
		if (!errors.empty()) break;
	}
	return errors;
}

double stress_pa(const StressStrainCurve& curve, double strain)
{
	const double e = std::fabs(strain);
	StressStrainPair before{};
	double stress = curve.pairs.empty() ? 0.0 : curve.pairs.back().stress_pa;
	for (const StressStrainPair& p : curve.pairs)
	{
		if (e <= p.strain)
		{
			stress = before.stress_pa + (p.stress_pa - before.stress_pa) * (e - before.strain) / (p.strain - before.strain);
			break;
		}
		before = p;
	}
	return strain < 0 ? -stress : stress;
}

double yieldStress_pa(const StressStrainCurve& curve) { return curve.pairs.empty() ? 0.0 : curve.pairs.front().stress_pa; }
double yieldStrain(const StressStrainCurve& curve) { return curve.pairs.empty() ? 0.0 : curve.pairs.front().strain; }

StressStrainCurve elasticPerfectlyPlastic(double youngs_modulus_pa, double yield_stress_pa, double ultimate_strain)
{
	return bilinear(youngs_modulus_pa, yield_stress_pa, 0.0, ultimate_strain);
}

StressStrainCurve bilinear(double youngs_modulus_pa, double yield_stress_pa, double hardening_ratio, double ultimate_strain)
{
	const double yieldStrain = yield_stress_pa / youngs_modulus_pa;
	StressStrainCurve c;
	c.pairs.push_back({yieldStrain, yield_stress_pa});
	if (ultimate_strain > yieldStrain)
		c.pairs.push_back({ultimate_strain, yield_stress_pa + hardening_ratio * youngs_modulus_pa * (ultimate_strain - yieldStrain)});
	return c;
}
namespace
{
// the whole of text (spaces around it allowed) as a finite number
bool wholeNumber(const std::string& text, double& value)
{
	const char* begin = text.c_str();
	char* end = nullptr;
	value = std::strtod(begin, &end);
	if (end == begin) return false;
	while (*end == ' ' || *end == '\t' || *end == '\r') end++;
	return *end == '\0' && std::isfinite(value);
}
}  // namespace

StressStrainCurve parseStressStrainCsv(const std::string& text, std::vector<std::string>& errors)
{
	StressStrainCurve curve;
	std::istringstream in(text);
	std::string line;
	const size_t errorsBefore = errors.size();
	bool first = true;
	for (int number = 1; std::getline(in, line); number++)
	{
		const size_t start = line.find_first_not_of(" \t\r");
		if (start == std::string::npos || line[start] == '#') continue;
		const size_t comma = line.find(',');
		double strain = 0, stress = 0;
		const bool numbers = comma != std::string::npos && wholeNumber(line.substr(0, comma), strain) && wholeNumber(line.substr(comma + 1), stress);
		if (!numbers && first && comma != std::string::npos)
		{
			first = false;  // a header of names
			continue;
		}
		first = false;
		if (!numbers)
		{
			std::ostringstream e;
			e << "stress-strain CSV line " << number << ": '" << line << "' is not two numbers 'strain,stress_pa'";
			errors.push_back(e.str());
			continue;
		}
		curve.pairs.push_back({strain, stress});
	}
	for (const std::string& e : validate(curve)) errors.push_back(e);
	if (errors.size() > errorsBefore) curve.pairs.clear();
	return curve;
}
}  // namespace plastic
