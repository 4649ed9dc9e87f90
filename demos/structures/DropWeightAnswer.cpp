#include "DropWeight.h"
#include "plastic/Section.h"

namespace structures
{
std::vector<std::string> validateDropWeightParameters(const DropWeightParameters& p)
{
	std::vector<std::string> e = scene::validateSolverSettings(p.solver);
	scene::requireRange(e, "span", p.span_m, 0.1, 100, "m");
	if (p.segments < 2 || p.segments > 1000 || p.segments % 2)
		e.push_back("segments: " + std::to_string(p.segments) + " is not an even number in [2, 1000]");
	scene::validateMember(p, e);
	scene::requireRange(e, "weight-mass", p.weight_mass_kg, 1e-3, 1e7, "kg");
	scene::requireRange(e, "weight-radius", p.weight_radius_m, 1e-3, 10, "m");
	scene::requireRange(e, "impact-speed", p.impact_speed_m_s, 1e-3, 1000, "m/s");
	scene::requireRange(e, "duration", p.duration_s, 1e-3, 1000, "s");
	if (e.empty() && p.duration_s / p.solver.world.internal_step_s > 1e8) e.push_back("duration / dt: more than 1e8 steps");
	return e;
}

DropWeightAnswer dropWeightAnswer(const DropWeightParameters& p)
{
	DropWeightAnswer a;
	plastic::Material m;
	m.yield_stress_pa = p.yield_stress_pa;
	const plastic::SectionProperties section = plastic::rectangle(p.section_width_m, p.section_depth_m);
	a.plastic_moment_nm = plastic::capacities(section, m).plastic_moment_y_nm;
	a.beam_mass_kg = p.density_kg_m3 * section.area_m2 * p.span_m;
	// a half: segments/2 boxes turning about the support, each about its own centre (length and depth) plus m r^2
	const double l = p.span_m / p.segments, ms = a.beam_mass_kg / p.segments;
	double inertiaHalf = 0;
	for (int i = 0; i < p.segments / 2; i++) inertiaHalf += ms * (l * l + p.section_depth_m * p.section_depth_m) / 12 + ms * ((i + 0.5) * l) * ((i + 0.5) * l);
	a.effective_mass_kg = 8 * inertiaHalf / (p.span_m * p.span_m);
	a.initial_kinetic_j = 0.5 * p.weight_mass_kg * p.impact_speed_m_s * p.impact_speed_m_s;
	a.kinetic_after_impact_j = a.initial_kinetic_j * p.weight_mass_kg / (p.weight_mass_kg + a.effective_mass_kg);
	a.half_rotation_rad = a.kinetic_after_impact_j / ((p.clamped ? 4 : 2) * a.plastic_moment_nm);
	a.midspan_rotation_rad = 2 * a.half_rotation_rad;
	a.support_rotation_rad = a.half_rotation_rad;
	return a;
}
}  // namespace structures
