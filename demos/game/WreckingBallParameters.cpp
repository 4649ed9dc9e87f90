#include <cmath>

#include "plastic/Section.h"
#include "scene/StructureRig.h"
#include "WreckingBall.h"

namespace game
{
using scene::requireRange;
using scene::requireWhole;

plastic::WorldSolverSettings wreckingBallSolverSettings()
{
	return plastic::WorldSolverSettings();
}

std::vector<std::string> validateWreckingBallParameters(const WreckingBallParameters& p)
{
	std::vector<std::string> e = plastic::validate(p.solver, "internal-step");
	scene::requireRange(e, "frame-rate", p.frame_rate_hz, 1, 1000, "Hz");
	scene::requireRange(e, "duration", p.duration_s, 0.01, 600, "s");
	scene::requireRange(e, "gravity", p.gravity_m_s2, 0.1, 100, "m/s2");
	scene::requireWhole(e, "storeys", p.storeys, 1, 20);
	scene::requireWhole(e, "bays", p.bays, 1, 20);
	scene::requireRange(e, "span", p.span_m, 0.5, 100, "m");
	scene::requireRange(e, "height", p.height_m, 0.5, 100, "m");
	scene::requireWhole(e, "column-segments", p.column_segments, 1, 64);
	scene::requireWhole(e, "beam-segments", p.beam_segments, 1, 64);
	scene::requireRange(e, "section-depth", p.section_depth_m, 0.01, 2, "m");
	scene::requireRange(e, "flange-width", p.flange_width_m, 0.01, 2, "m");
	scene::requireRange(e, "web-thickness", p.web_thickness_m, 1e-4, p.flange_width_m, "m");
	scene::requireRange(e, "flange-thickness", p.flange_thickness_m, 1e-4, 0.49 * p.section_depth_m, "m");
	scene::requireRange(e, "fy", p.yield_stress_pa, 1e6, 1e10, "Pa");
	scene::requireRange(e, "youngs-modulus", p.youngs_modulus_pa, 1e6, 1e13, "Pa");
	scene::requireRange(e, "density", p.density_kg_m3, 1, 1e5, "kg/m3");
	scene::requireRange(e, "max-plastic-rotation", p.max_plastic_rotation_rad, 1e-3, 100, "rad");
	scene::requireRange(e, "ball-mass", p.ball_mass_kg, 1, 1e6, "kg");
	scene::requireRange(e, "ball-radius", p.ball_radius_m, 0.05, 0.45 * p.height_m, "m");
	scene::requireRange(e, "chain-length", p.chain_length_m, 0.5, 100, "m");
	scene::requireWhole(e, "chain-links", p.chain_links, 1, 64);
	scene::requireRange(e, "chain-mass", p.chain_mass_kg, 0.1, 1e5, "kg");
	scene::requireRange(e, "release-angle", p.release_angle_rad, 0, 1.5, "rad");
	scene::requireRange(e, "impact-height", p.impact_height_m, p.ball_radius_m + 0.05, p.height_m, "m");
	scene::requireRange(e, "ball-friction", p.ball_friction, 0, 2, "");
	if (e.empty() && p.duration_s * p.frame_rate_hz > 1e6) e.push_back("duration x frame-rate: more than 1e6 frames");
	return e;
}

WreckingBallEstimate wreckingBallEstimate(const WreckingBallParameters& p)
{
	WreckingBallEstimate a;
	plastic::Material m;
	m.yield_stress_pa = p.yield_stress_pa;
	const plastic::SectionProperties s = plastic::iSection(p.section_depth_m, p.flange_width_m, p.web_thickness_m, p.flange_thickness_m);
	a.plastic_moment_nm = plastic::capacities(s, m).plastic_moment_y_nm;
	// heights above the bottom of the swing: each mass at distance d from the pivot rises d (1 - cos(release))
	const double drop = 1.0 - std::cos(p.release_angle_rad);
	const double R = p.chain_length_m + p.ball_radius_m;
	const double link = p.chain_length_m / p.chain_links;
	double chainMoment = 0, chainInertia = 0;  // sum of m d and m d^2 over the links (their centres)
	for (int i = 0; i < p.chain_links; i++)
	{
		const double d = (i + 0.5) * link, mi = p.chain_mass_kg / p.chain_links;
		chainMoment += mi * d;
		chainInertia += mi * d * d;
	}
	a.release_energy_j = p.gravity_m_s2 * drop * (p.ball_mass_kg * R + chainMoment);
	// swinging as one rigid pendulum (the ball's own spin about its centre included): E = I w^2 / 2, v = w R
	const double inertia = p.ball_mass_kg * R * R + 0.4 * p.ball_mass_kg * p.ball_radius_m * p.ball_radius_m + chainInertia;
	a.impact_speed_m_s = std::sqrt(2.0 * a.release_energy_j / inertia) * R;
	return a;
}

SteelFrameSpec steelFrameSpec(const WreckingBallParameters& p, const btVector3& origin_m)
{
	SteelFrameSpec spec;
	spec.origin_m = origin_m;
	spec.may_sleep = false;
	spec.storeys = p.storeys;
	spec.bays = p.bays;
	spec.span_m = p.span_m;
	spec.height_m = p.height_m;
	spec.column_segments = p.column_segments;
	spec.beam_segments = p.beam_segments;
	spec.joint.section = plastic::iSection(p.section_depth_m, p.flange_width_m, p.web_thickness_m, p.flange_thickness_m);
	spec.joint.material.yield_stress_pa = p.yield_stress_pa;
	spec.joint.material.youngs_modulus_pa = p.youngs_modulus_pa;
	spec.joint.material.density_kg_m3 = p.density_kg_m3;
	spec.joint.method = p.method;
	spec.joint.max_plastic_rotation_rad = p.max_plastic_rotation_rad;
	return spec;
}

PendulumSpec pendulumSpec(const WreckingBallParameters& p, const btVector3& origin_m)
{
	PendulumSpec pendulum;
	pendulum.bottom_m = origin_m + btVector3(btScalar(-(p.section_depth_m / 2 + p.ball_radius_m + 0.02)), btScalar(p.impact_height_m), 0);
	pendulum.ball_mass_kg = p.ball_mass_kg;
	pendulum.ball_radius_m = p.ball_radius_m;
	pendulum.ball_friction = p.ball_friction;
	pendulum.chain_length_m = p.chain_length_m;
	pendulum.chain_links = p.chain_links;
	pendulum.chain_mass_kg = p.chain_mass_kg;
	pendulum.release_angle_rad = p.release_angle_rad;
	pendulum.release_direction = -1;
	return pendulum;
}
}  // namespace game
