// Plastic analysis of the portal frame from its parameters: every mechanism is a combination a beam + b sway of
// the two independent ones; the least load factor Mp sum|rotations| / (work of the loads) over them is reached
// where a hinge site's rotation vanishes, so the candidates are the two mechanisms alone and, for each site, the
// combination in which that site does not turn.
#include <cmath>
#include <limits>

#include "Portal.h"
#include "plastic/Section.h"

namespace structures
{
std::vector<std::string> validatePortalParameters(const PortalParameters& p)
{
	std::vector<std::string> e = scene::validateSolverSettings(p.solver);
	scene::requireRange(e, "span", p.span_m, 0.1, 100, "m");
	scene::requireRange(e, "height", p.height_m, 0.1, 100, "m");
	scene::requireWhole(e, "column-segments", p.column_segments, 1, 100);
	if (p.beam_segments < 2 || p.beam_segments > 100 || p.beam_segments % 2)
		e.push_back("beam-segments: " + std::to_string(p.beam_segments) + " is not an even number in [2, 100]");
	scene::validateMember(p, e);
	scene::requireRange(e, "horizontal-load", p.horizontal_load_n, 0, 1e12, "N");
	scene::requireRange(e, "vertical-load", p.vertical_load_n, 0, 1e12, "N");
	if (e.empty() && p.sway_drifts.empty() && p.horizontal_load_n + p.vertical_load_n <= 0) e.push_back("horizontal-load, vertical-load: one of them must be > 0 N");
	scene::requireRange(e, "ramp-rate", p.ramp_rate_per_s, 0, 100, "1/s (0 = constant --load-factor)");
	scene::requireRange(e, "load-factor", p.load_factor, 0, 1000, "");
	validateCollapseRamp(p, e);
	scene::requireRange(e, "duration", p.duration_s, 1e-3, 10000, "s");
	scene::requireRange(e, "knee-load", p.knee_load_n, 0, 1e12, "N");
	scene::requireRange(e, "knee-load-ramp", p.knee_load_ramp_s, 1e-3, 100, "s");
	scene::requireDrifts(e, "sway-drifts", p.sway_drifts, 0.5, "(of h)");
	scene::requireRange(e, "drift-rate", p.drift_rate_per_s, 1e-6, 10, "1/s");
	scene::requireRange(e, "settle", p.settle_s, 0, 100, "s");
	if (e.empty() && p.duration_s / p.solver.world.internal_step_s > 1e8) e.push_back("duration / dt: more than 1e8 steps");
	return e;
}

double swaySecondOrderRatio(const PortalParameters& p, double drift)
{
	const double mp = portalAnswer(p).plastic_moment_nm;
	return (1 - 2 * p.knee_load_n * p.height_m * drift / (4 * mp)) / std::sqrt(1 - drift * drift);
}

PortalAnswer portalAnswer(const PortalParameters& p)
{
	PortalAnswer a;
	plastic::Material m;
	m.yield_stress_pa = p.yield_stress_pa;
	a.plastic_moment_nm = plastic::capacities(plastic::rectangle(p.section_width_m, p.section_depth_m), m).plastic_moment_y_nm;
	// members' rotations (counter-clockwise): beam mechanism: left half of the beam -1, right half +1 (mid-span
	// down); sway: both columns -1 (the knees move along +x). A site turns by (next member) - (previous member).
	a.sites.push_back({"base-left", 0, -1});
	for (int i = 1; i < p.column_segments; i++) a.sites.push_back({"column-left-" + std::to_string(i), 0, 0});
	a.sites.push_back({"knee-left", -1, 1});
	for (int i = 1; i < p.beam_segments; i++)
		a.sites.push_back({i == p.beam_segments / 2 ? std::string("mid-span") : "beam-" + std::to_string(i), i == p.beam_segments / 2 ? 2.0 : 0.0, 0});
	a.sites.push_back({"knee-right", -1, -1});
	for (int i = 1; i < p.column_segments; i++) a.sites.push_back({"column-right-" + std::to_string(i), 0, 0});
	a.sites.push_back({"base-right", 0, 1});
	const double beamWork = p.vertical_load_n * p.span_m / 2;  // per unit beam mechanism
	const double swayWork = p.horizontal_load_n * p.height_m;
	const double inf = std::numeric_limits<double>::infinity();
	auto factor = [&](double b, double s)
	{
		const double work = b * beamWork + s * swayWork;
		if (!(work > 1e-12 * (std::fabs(b) + std::fabs(s)) * (beamWork + swayWork))) return inf;
		double rotation = 0;
		for (const PortalJointSite& site : a.sites) rotation += std::fabs(b * site.beam_rotation + s * site.sway_rotation);
		return a.plastic_moment_nm * rotation / work;
	};
	a.beam_factor = factor(1, 0);
	a.sway_factor = factor(0, 1);
	a.combined_factor = factor(1, 1);
	std::vector<std::pair<double, double>> candidates = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
	for (const PortalJointSite& site : a.sites)
	{
		if (site.beam_rotation == 0 && site.sway_rotation == 0) continue;
		candidates.push_back({site.sway_rotation, -site.beam_rotation});
		candidates.push_back({-site.sway_rotation, site.beam_rotation});
	}
	a.collapse_factor = inf;
	double bestB = 0, bestS = 0;
	for (const auto& [b, s] : candidates)
	{
		const double f = factor(b, s);
		if (f < a.collapse_factor * (1 - 1e-12))
		{
			a.collapse_factor = f;
			bestB = b;
			bestS = s;
		}
	}
	a.mechanism = bestS == 0 ? "beam" : bestB == 0 ? "sway"
												   : (bestB == bestS ? "combined" : "combination");
	double largest = 0;
	for (const PortalJointSite& site : a.sites) largest = std::max(largest, std::fabs(bestB * site.beam_rotation + bestS * site.sway_rotation));
	for (size_t i = 0; i < a.sites.size(); i++)
	{
		const double r = (bestB * a.sites[i].beam_rotation + bestS * a.sites[i].sway_rotation) / largest;
		a.mechanism_rotations.push_back(r);
		if (std::fabs(r) > 1e-9) a.mechanism_sites.push_back(int(i));
	}
	return a;
}
}  // namespace structures
