#include "HingeLaw.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "SectionResponse.h"

namespace plastic
{
namespace
{
struct Point
{
	double curvature_1_m;
	double moment_nm;
};

// the largest distance (in moment) of the samples between corners a and b from the chord a-b, and where
double chordError(const std::vector<Point>& p, size_t a, size_t b, size_t& worst)
{
	double largest = 0;
	worst = a;
	for (size_t i = a + 1; i < b; i++)
	{
		const double t = (p[i].curvature_1_m - p[a].curvature_1_m) / (p[b].curvature_1_m - p[a].curvature_1_m);
		const double chord = p[a].moment_nm + t * (p[b].moment_nm - p[a].moment_nm);
		const double error = std::fabs(p[i].moment_nm - chord);
		if (error > largest)
		{
			largest = error;
			worst = i;
		}
	}
	return largest;
}

HingeLaw refused(std::string why)
{
	HingeLaw law;
	law.error = std::move(why);
	return law;
}
}  // namespace

HingeLaw hingeLaw(const SectionProperties& section, const StressStrainCurve& curve, double hinge_length_m, int max_layers)
{
	if (!section.error.empty()) return refused("hinge law: the section was refused: " + section.error);
	const std::vector<std::string> curveErrors = validate(curve);
	if (!curveErrors.empty()) return refused("hinge law: " + curveErrors.front());
	if (!(hinge_length_m > 0) || !std::isfinite(hinge_length_m))
	{
		std::ostringstream m;
		m << "hinge law: hinge_length_m = " << hinge_length_m << " is not in (0, inf)";
		return refused(m.str());
	}
	if (max_layers < 2 || max_layers > 16)
	{
		std::ostringstream m;
		m << "hinge law: max_layers = " << max_layers << " is not in [2, 16]";
		return refused(m.str());
	}
	const std::vector<SectionLayer> cut = sectionLayers(section, 2000);
	const double yieldCurvature = yieldStrain(curve) / (section.depth_m / 2);
	// the curve: linear to first yield, then sampled at curvatures spaced evenly in their logarithm up to 100 times it
	std::vector<Point> p{{0.0, 0.0}};
	const int samples = 240;
	for (int i = 0; i <= samples; i++)
	{
		const double k = yieldCurvature * std::pow(100.0, double(i) / samples);
		p.push_back({k, sectionForces(cut, curve, 0.0, k).moment_nm});
	}
	const double beyond = 2 * p.back().curvature_1_m;
	const double lastTangent = (sectionForces(cut, curve, 0.0, beyond).moment_nm - p.back().moment_nm) / (beyond - p.back().curvature_1_m);
	// corners: the origin, first yield and the last sample, then the sample farthest from its chord, until the layers
	// are used (one per corner after the origin, one for the last tangent when the curve still hardens there)
	const double largestMoment = p.back().moment_nm;
	const bool hardens = lastTangent > 1e-9 * p[1].moment_nm / p[1].curvature_1_m;
	const size_t corners = size_t(max_layers - (hardens ? 1 : 0)) + 1;
	std::vector<size_t> chosen{0, 1, p.size() - 1};
	while (chosen.size() < corners)
	{
		double largest = 0;
		size_t add = 0;
		for (size_t c = 0; c + 1 < chosen.size(); c++)
		{
			size_t worst;
			const double e = chordError(p, chosen[c], chosen[c + 1], worst);
			if (e > largest)
			{
				largest = e;
				add = worst;
			}
		}
		if (largest <= 1e-6 * largestMoment) break;
		chosen.insert(std::upper_bound(chosen.begin(), chosen.end(), add), add);
	}
	HingeLaw law;
	law.hinge_length_m = hinge_length_m;
	for (size_t c = 0; c + 1 < chosen.size(); c++)
	{
		size_t worst;
		law.max_error_fraction = std::max(law.max_error_fraction, chordError(p, chosen[c], chosen[c + 1], worst) / largestMoment);
	}
	// the tangents of the chosen chords, falling; layer m takes the fall of the tangent at corner m
	std::vector<double> tangent;
	for (size_t c = 0; c + 1 < chosen.size(); c++)
	{
		const Point& a = p[chosen[c]];
		const Point& b = p[chosen[c + 1]];
		tangent.push_back((b.moment_nm - a.moment_nm) / (b.curvature_1_m - a.curvature_1_m));
	}
	tangent.push_back(hardens ? lastTangent : 0.0);
	for (size_t m = 0; m + 1 < tangent.size(); m++)
	{
		const double fall = tangent[m] - tangent[m + 1];
		if (!(fall > 0))
		{
			std::ostringstream e;
			e << "hinge law: the section's moment-curvature tangent rises at curvature " << p[chosen[m + 1]].curvature_1_m
			  << " 1/m (a yield plateau before hardening?): parallel layers can only soften";
			return refused(e.str());
		}
		law.layers.push_back({fall / hinge_length_m, fall * p[chosen[m + 1]].curvature_1_m});
	}
	if (hardens) law.layers.push_back({tangent.back() / hinge_length_m, std::numeric_limits<double>::infinity()});
	return law;
}

double hingeMoment_nm(const HingeLaw& law, double rotation_rad)
{
	double m = 0;
	for (const HingeLayer& l : law.layers) m += std::copysign(std::min(l.stiffness_nm_rad * std::fabs(rotation_rad), l.max_moment_nm), rotation_rad);
	return m;
}
}  // namespace plastic
