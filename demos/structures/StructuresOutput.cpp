#include "StructuresOutput.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace structures
{
namespace
{
std::string number(double value)
{
	if (!std::isfinite(value)) return "null";
	char text[64];
	std::snprintf(text, sizeof text, "%.9g", value);
	return text;
}

// "key":value pairs in order
class Json
{
public:
	Json& add(const char* key, double value) { return raw(key, number(value)); }
	Json& add(const char* key, long value) { return raw(key, std::to_string(value)); }
	Json& add(const char* key, bool value) { return raw(key, value ? "true" : "false"); }
	Json& add(const char* key, const std::string& value) { return raw(key, "\"" + value + "\""); }
	Json& add(const char* key, const std::vector<double>& values)
	{
		std::string s = "[";
		for (size_t i = 0; i < values.size(); i++) s += (i ? "," : "") + number(values[i]);
		return raw(key, s + "]");
	}
	Json& add(const char* key, const std::vector<std::string>& values)
	{
		std::string s = "[";
		for (size_t i = 0; i < values.size(); i++) s += (i ? ",\"" : "\"") + values[i] + "\"";
		return raw(key, s + "]");
	}
	Json& raw(const char* key, const std::string& value)
	{
		m_text += (m_text.empty() ? "{\"" : ",\"") + std::string(key) + "\":" + value;
		return *this;
	}
	std::string str() const { return m_text + "}"; }

private:
	std::string m_text;
};

Json solverJson(const char* scene, const scene::SolverSettings& s)
{
	Json j;
	j.add("scene", std::string(scene)).add("method", std::string(plastic::jointMethodName(s.method))).add("solver", std::string(plastic::solverKindName(s.world.solver))).add("dt", s.world.internal_step_s).add("iterations", long(s.world.iterations)).add("erp", s.world.erp);
	return j;
}

std::vector<std::string> siteNames(const PortalAnswer& a, const std::vector<int>& sites)
{
	std::vector<std::string> names;
	for (int i : sites) names.push_back(a.sites[size_t(i)].name);
	return names;
}

std::string joinNames(const std::vector<std::string>& names)
{
	std::string s;
	for (size_t i = 0; i < names.size(); i++) s += (i ? ", " : "") + names[i];
	return s.empty() ? "none" : s;
}
}  // namespace

std::string toJson(const CantileverParameters& p, const CantileverResult& r)
{
	Json j = solverJson("cantilever", p.solver);
	std::vector<std::string> mechanism;
	for (int i : r.mechanism) mechanism.push_back(i == 0 ? "root" : "inner-" + std::to_string(i));
	// a pushover's load_ratio is the one it measured at its drift (P L / Mp); otherwise the load ratio it was given
	j.add("follower", p.follower_load).add("ramp", p.ramp_rate_per_s > 0).add("load_ratio", p.tip_drift > 0 ? r.drift_load_ratio : p.load_ratio).add("tip_drift", p.tip_drift).add("measured_tip_drift", r.measured_tip_drift).add("stress_strain_pairs", long(p.stress_strain ? p.stress_strain->pairs.size() : 0)).add("half_length_support", p.support_joint_half_length).add("plastic_moment_Nm", r.answer.plastic_moment_nm).add("analytic_collapse_load_N", r.answer.collapse_load_n).add("collapse_ratio", r.collapse_ratio).add("collapse_error_pct", 100 * (r.collapse_ratio - r.answer.collapse_ratio) / r.answer.collapse_ratio).add("holds", long(r.holds)).add("mechanism", mechanism).add("analytic_stop_rotation_rad", r.answer.stop_rotation_rad).add("stop_rotation_rad", r.stop_rotation_rad).add("stop_error_pct", 100 * (r.stop_rotation_rad - r.answer.stop_rotation_rad) / r.answer.stop_rotation_rad).add("root_rotation_rad", r.root_rotation_rad).add("max_root_rotation_rad", r.max_root_rotation_rad).add("max_inner_rotation_rad", r.max_inner_rotation_rad).add("creep_rad", r.creep_rad).add("load_work_J", r.load_work_j).add("kinetic_J", r.kinetic_j).add("geometric_plastic_work_J", r.geometric_plastic_work_j).add("booked_plastic_work_J", r.booked_plastic_work_j).add("energy_balance_error_pct", r.energy_balance_error_pct).add("solver_fallbacks", long(r.solver_fallbacks)).add("steps", r.steps).add("simulated_s", r.simulated_s).add("wall_s", r.wall_s).add("finite", r.finite);
	return j.str();
}

std::string toJson(const PortalParameters& p, const PortalResult& r)
{
	Json j = solverJson("portal", p.solver);
	const PortalAnswer& a = r.answer;
	std::vector<std::string> sites;
	for (const PortalJointSite& s : a.sites) sites.push_back(s.name);
	j.add("ramp", p.ramp_rate_per_s > 0).add("load_factor", p.load_factor).add("horizontal_load_N", p.horizontal_load_n).add("vertical_load_N", p.vertical_load_n).add("plastic_moment_Nm", a.plastic_moment_nm).add("beam_factor", a.beam_factor).add("sway_factor", a.sway_factor).add("combined_factor", a.combined_factor).add("analytic_collapse_factor", a.collapse_factor).add("analytic_mechanism", a.mechanism).add("analytic_hinges", siteNames(a, a.mechanism_sites)).add("collapse_factor", r.collapse_factor).add("collapse_error_pct", r.collapse_error_pct).add("holds", long(r.holds)).add("hinges", siteNames(a, r.mechanism_sites)).add("mechanism_matches", r.mechanism_matches).add("sites", sites).add("analytic_mechanism_rotations", a.mechanism_rotations).add("mechanism_rotations_rad", r.mechanism_rotations_rad).add("rotations_rad", r.rotations_rad).add("max_rotation_rad", r.max_rotation_rad).add("creep_rad", r.creep_rad).add("load_work_J", r.load_work_j).add("kinetic_J", r.kinetic_j).add("geometric_plastic_work_J", r.geometric_plastic_work_j).add("booked_plastic_work_J", r.booked_plastic_work_j).add("solver_fallbacks", long(r.solver_fallbacks)).add("steps", r.steps).add("simulated_s", r.simulated_s).add("wall_s", r.wall_s).add("finite", r.finite);
	return j.str();
}

std::string toJson(const DropWeightParameters& p, const DropWeightResult& r)
{
	Json j = solverJson("drop-weight", p.solver);
	const DropWeightAnswer& a = r.answer;
	j.add("clamped", p.clamped).add("plastic_moment_Nm", a.plastic_moment_nm).add("beam_mass_kg", a.beam_mass_kg).add("effective_mass_kg", a.effective_mass_kg).add("initial_kinetic_J", a.initial_kinetic_j).add("analytic_kinetic_after_impact_J", a.kinetic_after_impact_j).add("kinetic_after_impact_J", r.kinetic_after_impact_j).add("analytic_midspan_rotation_rad", a.midspan_rotation_rad).add("midspan_rotation_rad", r.midspan_rotation_rad).add("midspan_error_pct", r.midspan_error_pct).add("analytic_support_rotation_rad", a.support_rotation_rad).add("left_support_rotation_rad", r.left_support_rotation_rad).add("right_support_rotation_rad", r.right_support_rotation_rad).add("max_inner_rotation_rad", r.max_inner_rotation_rad).add("kinetic_end_J", r.kinetic_end_j).add("geometric_plastic_work_J", r.geometric_plastic_work_j).add("booked_plastic_work_J", r.booked_plastic_work_j).add("plastic_work_error_pct", r.plastic_work_error_pct).add("balance_error_pct", r.balance_error_pct).add("solver_fallbacks", long(r.solver_fallbacks)).add("steps", r.steps).add("simulated_s", r.simulated_s).add("wall_s", r.wall_s).add("finite", r.finite);
	return j.str();
}

std::string toSummary(const CantileverParameters& p, const CantileverResult& r)
{
	std::ostringstream out;
	out << "cantilever, " << plastic::jointMethodName(p.solver.method) << ", " << plastic::solverKindName(p.solver.world.solver) << ", dt " << p.solver.world.internal_step_s << " s, " << p.solver.world.iterations
		<< " iterations: " << r.steps << " steps (" << r.simulated_s << " s simulated, " << r.solver_fallbacks << " solver fallbacks) in " << r.wall_s << " s\n";
	out << "  Mp " << r.answer.plastic_moment_nm << " N m, analytic collapse load Mp / L = " << r.answer.collapse_load_n << " N\n";
	if (p.tip_drift > 0)
		out << "  pushover to a tip drift of " << p.tip_drift << " (reached " << r.measured_tip_drift << "): P L / Mp = " << r.drift_load_ratio
			<< (p.stress_strain ? " (hardening joints, " + std::to_string(p.stress_strain->pairs.size()) + " pairs)" : std::string()) << "\n";
	else if (p.ramp_rate_per_s > 0)
		out << "  collapse seen at P L / Mp = " << r.collapse_ratio << " (analytic 1), joints in the mechanism: " << r.mechanism.size()
			<< (r.mechanism == std::vector<int>{0} ? " (the root)" : "") << "\n";
	else
		out << "  " << (p.follower_load ? "follower" : "dead") << " load P L / Mp = " << p.load_ratio << ": stopped at " << r.stop_rotation_rad
			<< " rad (analytic " << r.answer.stop_rotation_rad << " rad), root rotation at the end " << r.root_rotation_rad << " rad\n";
	out << "  load work " << r.load_work_j << " J = kinetic " << r.kinetic_j << " J + Mp x rotations " << r.geometric_plastic_work_j
		<< " J (balance error " << r.energy_balance_error_pct << " %); booked plastic work " << r.booked_plastic_work_j
		<< " J; largest inner joint rotation " << r.max_inner_rotation_rad << " rad\n";
	return out.str();
}

std::string toSummary(const PortalParameters& p, const PortalResult& r)
{
	std::ostringstream out;
	const PortalAnswer& a = r.answer;
	out << "portal frame, " << plastic::jointMethodName(p.solver.method) << ", " << plastic::solverKindName(p.solver.world.solver) << ", dt " << p.solver.world.internal_step_s << " s, " << p.solver.world.iterations
		<< " iterations: " << r.steps << " steps (" << r.simulated_s << " s simulated, " << r.solver_fallbacks << " solver fallbacks) in " << r.wall_s << " s\n";
	out << "  plastic analysis: beam " << a.beam_factor << ", sway " << a.sway_factor << ", combined " << a.combined_factor << " -> collapse factor "
		<< a.collapse_factor << " (" << a.mechanism << ": " << joinNames(siteNames(a, a.mechanism_sites)) << ")\n";
	if (p.ramp_rate_per_s > 0)
		out << "  simulated: collapse factor " << r.collapse_factor << " (" << r.collapse_error_pct << " %), hinges "
			<< joinNames(siteNames(a, r.mechanism_sites)) << (r.mechanism_matches ? " (as predicted)" : " (NOT as predicted)") << "\n";
	else
		out << "  load factor held at " << p.load_factor << ": largest site rotation " << r.max_rotation_rad << " rad, creep over the last two thirds "
			<< r.creep_rad << " rad\n";
	out << "  load work " << r.load_work_j << " J, kinetic " << r.kinetic_j << " J, Mp x rotations " << r.geometric_plastic_work_j
		<< " J, booked plastic work " << r.booked_plastic_work_j << " J\n";
	return out.str();
}

std::string toSummary(const DropWeightParameters& p, const DropWeightResult& r)
{
	std::ostringstream out;
	const DropWeightAnswer& a = r.answer;
	out << "drop weight on a " << (p.clamped ? "clamped" : "simply supported") << " beam, " << plastic::jointMethodName(p.solver.method) << ", " << plastic::solverKindName(p.solver.world.solver) << ", dt "
		<< p.solver.world.internal_step_s << " s, " << p.solver.world.iterations << " iterations: " << r.steps << " steps (" << r.simulated_s << " s simulated, " << r.solver_fallbacks << " solver fallbacks) in "
		<< r.wall_s << " s\n";
	out << "  ball " << a.initial_kinetic_j << " J; kinetic energy after the impact " << r.kinetic_after_impact_j << " J (estimate "
		<< a.kinetic_after_impact_j << " J)\n";
	out << "  mid-span rotation " << r.midspan_rotation_rad << " rad (estimate " << a.midspan_rotation_rad << " rad, " << r.midspan_error_pct
		<< " %), supports " << r.left_support_rotation_rad << " and " << r.right_support_rotation_rad << " rad (estimate " << a.support_rotation_rad
		<< " rad)\n";
	out << "  Mp x rotations " << r.geometric_plastic_work_j << " J (" << r.plastic_work_error_pct << " % against the estimate), booked "
		<< r.booked_plastic_work_j << " J, kinetic at the end " << r.kinetic_end_j << " J, balance error " << r.balance_error_pct << " %\n";
	return out.str();
}
}  // namespace structures
