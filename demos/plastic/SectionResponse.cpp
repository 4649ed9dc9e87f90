#include "SectionResponse.h"

#include <algorithm>
#include <cmath>

namespace plastic
{
namespace
{
// the width (m) of the section at z across its depth (|z| <= depth / 2)
double widthAt_m(const SectionProperties& s, double z)
{
	const double a = std::fabs(z);
	const double half = s.depth_m / 2;
	if (s.shape == "round bar") return 2 * std::sqrt(std::max(0.0, half * half - a * a));
	if (s.shape == "tube")
	{
		const double inner = half - s.wall_m;
		return 2 * std::sqrt(std::max(0.0, half * half - a * a)) - (a < inner ? 2 * std::sqrt(inner * inner - a * a) : 0.0);
	}
	if (s.shape == "I section") return a > half - s.flange_thickness_m ? s.width_m : s.web_thickness_m;
	return s.width_m;  // rectangle, notched rectangle
}
}  // namespace

std::vector<SectionLayer> sectionLayers(const SectionProperties& section, int count)
{
	std::vector<SectionLayer> layers;
	if (!section.error.empty() || count < 1 || !(section.depth_m > 0)) return layers;
	const double thickness = section.depth_m / count;
	for (int i = 0; i < count; i++)
	{
		const double z = -section.depth_m / 2 + (i + 0.5) * thickness;
		layers.push_back({z, widthAt_m(section, z) * thickness});
	}
	return layers;
}

SectionForces sectionForces(const std::vector<SectionLayer>& layers, const StressStrainCurve& curve, double axial_strain, double curvature_1_m)
{
	SectionForces f;
	for (const SectionLayer& l : layers)
	{
		const double force = stress_pa(curve, axial_strain + curvature_1_m * l.z_m) * l.area_m2;
		f.axial_n += force;
		f.moment_nm += force * l.z_m;
	}
	return f;
}

std::vector<MomentCurvaturePoint> momentCurvature(const SectionProperties& section, const StressStrainCurve& curve, double max_curvature_1_m, int count,
												  int layers)
{
	std::vector<MomentCurvaturePoint> points;
	const std::vector<SectionLayer> cut = sectionLayers(section, layers);
	if (cut.empty() || count < 1) return points;
	for (int i = 0; i <= count; i++)
	{
		const double k = max_curvature_1_m * i / count;
		points.push_back({k, sectionForces(cut, curve, 0.0, k).moment_nm});
	}
	return points;
}
}  // namespace plastic
