#include "StressStrain.h"

#include <cmath>
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
}  // namespace plastic
