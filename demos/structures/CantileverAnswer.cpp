#include <cmath>
#include <sstream>
#include <limits>

#include "Cantilever.h"
#include "plastic/Section.h"

namespace structures
{
std::vector<std::string> validateCantileverParameters(const CantileverParameters& p)
{
	std::vector<std::string> e = scene::validateSolverSettings(p.solver);
	scene::requireRange(e, "length", p.length_m, 0.01, 100, "m");
	scene::requireWhole(e, "segments", p.segments, 1, 1000);
	scene::validateMember(p, e);
	scene::requireRange(e, "load-ratio", p.load_ratio, 0, 100, "(P L / Mp)");
	scene::requireRange(e, "ramp-rate", p.ramp_rate_per_s, 0, 100, "1/s (0 = constant load)");
	validateCollapseRamp(p, e);
	scene::requireRange(e, "duration", p.duration_s, 1e-3, 1000, "s");
	scene::requireRange(e, "tip-drift", p.tip_drift, 0, 1, "(of the length; 0 = a load, not a pushover)");
	scene::requireRange(e, "drift-rate", p.drift_rate_per_s, 1e-4, 10, "1/s (of the length)");
	scene::requireRange(e, "settle", p.settle_s, 0.2, 100, "s");
	if (p.tip_drift > 0 && p.ramp_rate_per_s > 0) e.push_back("tip-drift and ramp-rate: a pushover drives the tip, it does not ramp a load (one or the other)");
	if (p.tip_drift > 0 && p.follower_load) e.push_back("tip-drift and follower: the actuator drives the tip along y (one or the other)");
	if (!p.cyclic_drifts.empty())
	{
		if (p.tip_drift > 0) e.push_back("cyclic-drifts and tip-drift: a cyclic pushover's last drift is its own (one or the other)");
		if (p.ramp_rate_per_s > 0 || p.follower_load) e.push_back("cyclic-drifts: a pushover drives the tip along y, with no ramp and no follower load");
		scene::requireDrifts(e, "cyclic-drifts", p.cyclic_drifts, 1, "(of the length)");
	}
	if (p.stress_strain)
	{
		if (p.solver.method != plastic::JointMethod::ElasticPlastic2)
			e.push_back(std::string("stress-strain: only elastic-plastic2 joints harden, not ") + plastic::jointMethodName(p.solver.method));
		for (const std::string& c : plastic::validate(*p.stress_strain)) e.push_back("stress-strain: " + c);
	}
	if (e.empty() && p.duration_s / p.solver.world.internal_step_s > 1e8) e.push_back("duration / dt: more than 1e8 steps");
	return e;
}

CantileverAnswer cantileverAnswer(const CantileverParameters& p)
{
	CantileverAnswer a;
	plastic::Material m;
	// Mp = fy W_pl, fy the curve's first yield when the joints follow a curve
	m.yield_stress_pa = p.stress_strain && !p.stress_strain->pairs.empty() ? plastic::yieldStress_pa(*p.stress_strain) : p.yield_stress_pa;
	a.plastic_moment_nm = plastic::capacities(plastic::rectangle(p.section_width_m, p.section_depth_m), m).plastic_moment_y_nm;
	a.collapse_load_n = a.plastic_moment_nm / p.length_m;
	a.collapse_ratio = 1.0;
	const double lambda = p.load_ratio;
	if (lambda <= 1.0)
	{
		a.stop_rotation_rad = 0;
	}
	else if (p.follower_load)
	{
		a.stop_rotation_rad = std::numeric_limits<double>::quiet_NaN();  // the follower's work P L theta always beats Mp theta
	}
	else
	{
		// the root of f(theta) = lambda sin(theta) - theta in (0, pi): f > 0 just above 0, f(pi) < 0; bisection
		double lo = 1e-9, hi = M_PI;
		for (int i = 0; i < 200; i++)
		{
			const double mid = 0.5 * (lo + hi);
			(lambda * std::sin(mid) - mid > 0 ? lo : hi) = mid;
		}
		a.stop_rotation_rad = 0.5 * (lo + hi);
	}
	return a;
}
}  // namespace structures
