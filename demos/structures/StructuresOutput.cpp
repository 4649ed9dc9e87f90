#include "StructuresOutput.h"

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <sstream>

#include "scene/JsonNumber.h"

namespace structures
{
namespace
{
// "key":value pairs in order
class Json
{
public:
	Json& add(const char* key, double value) { return raw(key, scene::jsonNumber(value)); }
	Json& add(const char* key, long value) { return raw(key, std::to_string(value)); }
	Json& add(const char* key, bool value) { return raw(key, value ? "true" : "false"); }
	Json& add(const char* key, const std::string& value) { return raw(key, "\"" + value + "\""); }
	Json& add(const char* key, const std::vector<double>& values)
	{
		std::string s = "[";
		for (size_t i = 0; i < values.size(); i++) s += (i ? "," : "") + scene::jsonNumber(values[i]);
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
	j.add("follower", p.follower_load).add("ramp", p.ramp_rate_per_s > 0).add("load_ratio", p.tip_drift > 0 ? r.drift_load_ratio : p.load_ratio).add("tip_drift", p.tip_drift).add("measured_tip_drift", r.measured_tip_drift).add("cyclic_drifts", p.cyclic_drifts).add("cyclic_load_ratios", r.cyclic_load_ratios).add("cyclic_measured_drifts", r.cyclic_measured_drifts).add("stress_strain_pairs", long(p.stress_strain ? p.stress_strain->pairs.size() : 0)).add("half_length_support", p.support_joint_half_length).add("plastic_moment_Nm", r.answer.plastic_moment_nm).add("analytic_collapse_load_N", r.answer.collapse_load_n).add("collapse_ratio", r.collapse_ratio).add("collapse_error_pct", 100 * (r.collapse_ratio - r.answer.collapse_ratio) / r.answer.collapse_ratio).add("holds", long(r.holds)).add("mechanism", mechanism).add("analytic_stop_rotation_rad", r.answer.stop_rotation_rad).add("stop_rotation_rad", r.stop_rotation_rad).add("stop_error_pct", 100 * (r.stop_rotation_rad - r.answer.stop_rotation_rad) / r.answer.stop_rotation_rad).add("root_rotation_rad", r.root_rotation_rad).add("max_root_rotation_rad", r.max_root_rotation_rad).add("max_inner_rotation_rad", r.max_inner_rotation_rad).add("creep_rad", r.creep_rad).add("load_work_J", r.load_work_j).add("kinetic_J", r.kinetic_j).add("geometric_plastic_work_J", r.geometric_plastic_work_j).add("booked_plastic_work_J", r.booked_plastic_work_j).add("energy_balance_error_pct", r.energy_balance_error_pct).add("solver_fallbacks", long(r.solver_fallbacks)).add("steps", r.internal_steps).add("simulated_s", r.simulated_s).add("wall_s", r.wall_s).add("finite", r.finite);
	return j.str();
}

std::string toJson(const PortalParameters& p, const PortalResult& r)
{
	Json j = solverJson("portal", p.solver);
	const PortalAnswer& a = r.answer;
	std::vector<std::string> sites;
	for (const PortalJointSite& s : a.sites) sites.push_back(s.name);
	j.add("ramp", p.ramp_rate_per_s > 0 && p.sway_drifts.empty()).add("load_factor", p.load_factor).add("horizontal_load_N", p.horizontal_load_n).add("vertical_load_N", p.vertical_load_n).add("knee_load_N", p.knee_load_n).add("sway_drifts", p.sway_drifts).add("sway_load_ratios", r.sway_load_ratios).add("sway_measured_drifts", r.sway_measured_drifts).add("second_order_load_ratios", r.second_order_load_ratios).add("plastic_moment_Nm", a.plastic_moment_nm).add("beam_factor", a.beam_factor).add("sway_factor", a.sway_factor).add("combined_factor", a.combined_factor).add("analytic_collapse_factor", a.collapse_factor).add("analytic_mechanism", a.mechanism).add("analytic_hinges", siteNames(a, a.mechanism_sites)).add("collapse_factor", r.collapse_factor).add("collapse_error_pct", r.collapse_error_pct).add("holds", long(r.holds)).add("hinges", siteNames(a, r.mechanism_sites)).add("mechanism_matches", r.mechanism_matches).add("sites", sites).add("analytic_mechanism_rotations", a.mechanism_rotations).add("mechanism_rotations_rad", r.mechanism_rotations_rad).add("rotations_rad", r.rotations_rad).add("max_rotation_rad", r.max_rotation_rad).add("creep_rad", r.creep_rad).add("load_work_J", r.load_work_j).add("kinetic_J", r.kinetic_j).add("geometric_plastic_work_J", r.geometric_plastic_work_j).add("booked_plastic_work_J", r.booked_plastic_work_j).add("elastic_J", r.elastic_j).add("energy_balance_error_pct", r.energy_balance_error_pct).add("solver_fallbacks", long(r.solver_fallbacks)).add("steps", r.internal_steps).add("simulated_s", r.simulated_s).add("wall_s", r.wall_s).add("finite", r.finite);
	return j.str();
}

std::string toJson(const DropWeightParameters& p, const DropWeightResult& r)
{
	Json j = solverJson("drop-weight", p.solver);
	const DropWeightAnswer& a = r.answer;
	j.add("clamped", p.clamped).add("plastic_moment_Nm", a.plastic_moment_nm).add("beam_mass_kg", a.beam_mass_kg).add("effective_mass_kg", a.effective_mass_kg).add("initial_kinetic_J", a.initial_kinetic_j).add("analytic_kinetic_after_impact_J", a.kinetic_after_impact_j).add("kinetic_after_impact_J", r.kinetic_after_impact_j).add("analytic_midspan_rotation_rad", a.midspan_rotation_rad).add("midspan_rotation_rad", r.midspan_rotation_rad).add("midspan_error_pct", r.midspan_error_pct).add("analytic_support_rotation_rad", a.support_rotation_rad).add("left_support_rotation_rad", r.left_support_rotation_rad).add("right_support_rotation_rad", r.right_support_rotation_rad).add("max_inner_rotation_rad", r.max_inner_rotation_rad).add("kinetic_end_J", r.kinetic_end_j).add("geometric_plastic_work_J", r.geometric_plastic_work_j).add("booked_plastic_work_J", r.booked_plastic_work_j).add("elastic_end_J", r.elastic_end_j).add("plastic_work_error_pct", r.plastic_work_error_pct).add("balance_error_pct", r.balance_error_pct).add("solver_fallbacks", long(r.solver_fallbacks)).add("steps", r.internal_steps).add("simulated_s", r.simulated_s).add("wall_s", r.wall_s).add("finite", r.finite);
	return j.str();
}

std::string toSummary(const CantileverParameters& p, const CantileverResult& r)
{
	std::ostringstream out;
	out << "cantilever, " << plastic::jointMethodName(p.solver.method) << ", " << plastic::solverKindName(p.solver.world.solver) << ", dt " << p.solver.world.internal_step_s << " s, " << p.solver.world.iterations
		<< " iterations: " << r.internal_steps << " steps (" << r.simulated_s << " s simulated, " << r.solver_fallbacks << " solver fallbacks) in " << r.wall_s << " s\n";
	out << "  Mp " << r.answer.plastic_moment_nm << " N m, analytic collapse load Mp / L = " << r.answer.collapse_load_n << " N\n";
	if (!p.cyclic_drifts.empty())
	{
		out << "  cyclic pushover, P L / Mp before each drift:";
		for (size_t k = 0; k < r.cyclic_load_ratios.size(); k++) out << " " << r.cyclic_load_ratios[k] << " at " << r.cyclic_measured_drifts[k] << ";";
		out << "\n";
	}
	else if (p.tip_drift > 0)
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
		<< " iterations: " << r.internal_steps << " steps (" << r.simulated_s << " s simulated, " << r.solver_fallbacks << " solver fallbacks) in " << r.wall_s << " s\n";
	if (p.sway_drifts.empty())
		out << "  plastic analysis: beam " << a.beam_factor << ", sway " << a.sway_factor << ", combined " << a.combined_factor << " -> collapse factor "
			<< a.collapse_factor << " (" << a.mechanism << ": " << joinNames(siteNames(a, a.mechanism_sites)) << ")\n";
	if (!p.sway_drifts.empty())
	{
		out << "  sway pushover with " << p.knee_load_n << " N on each knee, H h / (4 Mp) before each drift (rigid-plastic, second order):";
		for (size_t k = 0; k < r.sway_load_ratios.size(); k++)
			out << " " << r.sway_load_ratios[k] << " at " << r.sway_measured_drifts[k] << " (" << r.second_order_load_ratios[k] << ");";
		out << "\n";
	}
	else if (p.ramp_rate_per_s > 0)
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
		<< p.solver.world.internal_step_s << " s, " << p.solver.world.iterations << " iterations: " << r.internal_steps << " steps (" << r.simulated_s << " s simulated, " << r.solver_fallbacks << " solver fallbacks) in "
		<< r.wall_s << " s\n";
	out << "  ball " << a.initial_kinetic_j << " J; energy after the impact " << r.kinetic_after_impact_j << " J (estimate "
		<< a.kinetic_after_impact_j << " J)\n";
	out << "  mid-span rotation " << r.midspan_rotation_rad << " rad (estimate " << a.midspan_rotation_rad << " rad, " << r.midspan_error_pct
		<< " %), supports " << r.left_support_rotation_rad << " and " << r.right_support_rotation_rad << " rad (estimate " << a.support_rotation_rad
		<< " rad)\n";
	out << "  Mp x rotations " << r.geometric_plastic_work_j << " J (" << r.plastic_work_error_pct << " % against the estimate), booked "
		<< r.booked_plastic_work_j << " J, elastic at the end " << r.elastic_end_j << " J, kinetic at the end " << r.kinetic_end_j << " J, balance error "
		<< r.balance_error_pct << " %\n";
	return out.str();
}
std::string toJson(const PaperClipParameters& p, const PaperClipResult& r)
{
	Json j = solverJson("paper-clip", p.solver);
	const PaperClipAnswer& a = r.answer;
	j.add("wire_diameter_m", p.wire_diameter_m).add("amplitude_rad", p.bend_amplitude_rad).add("period_s", p.cycle_period_s).add("hinge_length_m", p.hinge_length_m).add("reduction_of_area", p.reduction_of_area).add("plastic_moment_Nm", a.plastic_moment_nm).add("ductility_rotation_rad", a.ductility_rotation_rad).add("ductility_exponent", a.ductility_exponent).add("analytic_break_time_s", a.break_time_s).add("analytic_cycles_to_break", a.cycles_to_break).add("constant_amplitude_cycles", a.constant_amplitude_cycles).add("broken", r.broken).add("break_time_s", r.break_time_s).add("cycles_to_break", r.cycles_to_break).add("cycles_error_pct", 100 * (r.cycles_to_break - a.cycles_to_break) / a.cycles_to_break).add("fatigue_damage", r.fatigue_damage).add("plastic_rotation_rad", r.plastic_rotation_rad).add("peak_moment_Nm", r.peak_moment_nm).add("hand_work_J", r.hand_work_j).add("booked_plastic_work_J", r.plastic_work_j).add("elastic_J", r.elastic_j).add("kinetic_J", r.kinetic_j).add("start_kinetic_J", r.start_kinetic_j).add("energy_balance_error_pct", r.energy_balance_error_pct).add("steps", r.internal_steps).add("simulated_s", r.simulated_s).add("finite", r.finite);
	return j.str();
}

std::string toSummary(const PaperClipParameters& p, const PaperClipResult& r)
{
	std::ostringstream out;
	const PaperClipAnswer& a = r.answer;
	out << "paper clip, " << plastic::jointMethodName(p.solver.method) << ", " << plastic::solverKindName(p.solver.world.solver) << ", dt " << p.solver.world.internal_step_s << " s: " << r.internal_steps
		<< " steps (" << r.simulated_s << " s simulated)\n";
	out << "  wire " << p.wire_diameter_m * 1e3 << " mm bent +-" << p.bend_amplitude_rad << " rad every " << p.cycle_period_s << " s; Mp " << a.plastic_moment_nm
		<< " N m; Coffin-Manson theta_f " << a.ductility_rotation_rad << " rad, c " << a.ductility_exponent << "\n";
	out << "  " << (r.broken ? "broke after " + scene::jsonNumber(r.cycles_to_break) + " cycles" : std::string("did not break")) << " (Coffin-Manson and Miner on the driven angle: "
		<< a.cycles_to_break << " cycles; constant amplitude from the start: " << a.constant_amplitude_cycles << "), fatigue damage " << r.fatigue_damage << "\n";
	out << "  hand's work " << r.hand_work_j << " J = booked plastic " << r.plastic_work_j << " J + elastic " << r.elastic_j << " J + kinetic change "
		<< r.kinetic_j - r.start_kinetic_j << " J (balance error " << r.energy_balance_error_pct << " %); peak moment " << r.peak_moment_nm << " N m\n";
	return out.str();
}

std::string hysteresisSvg(const PaperClipParameters& p, const PaperClipResult& r)
{
	const double width = 640, height = 480, left = 70, right = 20, top = 40, bottom = 50;
	const double mp = r.answer.plastic_moment_nm;
	double xMax = p.bend_amplitude_rad * 1.1, yMax = 1.2;
	for (const HysteresisSample& s : r.hysteresis) yMax = std::max(yMax, 1.05 * std::fabs(s.moment_nm) / mp);
	yMax = std::min(yMax, 5.0);
	auto X = [&](double x) { return left + (x + xMax) / (2 * xMax) * (width - left - right); };
	auto Y = [&](double y) { return top + (yMax - std::max(-yMax, std::min(yMax, y))) / (2 * yMax) * (height - top - bottom); };
	std::ostringstream svg;
	char buf[256];
	svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
	svg << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
	std::snprintf(buf, sizeof buf, "paper clip, %s: moment / Mp against rotation; %s", plastic::jointMethodName(p.solver.method),
				  r.broken ? ("broke after " + scene::jsonNumber(r.cycles_to_break) + " cycles (rule: " + scene::jsonNumber(r.answer.cycles_to_break) + ")").c_str() : "not broken");
	svg << "<text x=\"" << left << "\" y=\"22\">" << buf << "</text>\n";
	// axes and the +-Mp lines
	svg << "<line x1=\"" << X(-xMax) << "\" y1=\"" << Y(0) << "\" x2=\"" << X(xMax) << "\" y2=\"" << Y(0) << "\" stroke=\"black\"/>\n";
	svg << "<line x1=\"" << X(0) << "\" y1=\"" << Y(yMax) << "\" x2=\"" << X(0) << "\" y2=\"" << Y(-yMax) << "\" stroke=\"black\"/>\n";
	for (double m : {1.0, -1.0})
		svg << "<line x1=\"" << X(-xMax) << "\" y1=\"" << Y(m) << "\" x2=\"" << X(xMax) << "\" y2=\"" << Y(m) << "\" stroke=\"gray\" stroke-dasharray=\"4 4\"/>\n";
	svg << "<text x=\"" << X(xMax) - 60 << "\" y=\"" << Y(1) - 4 << "\" fill=\"gray\">M = Mp</text>\n";
	svg << "<text x=\"" << (left + width - right) / 2 - 40 << "\" y=\"" << height - 12 << "\">rotation, rad (+-" << scene::jsonNumber(xMax) << ")</text>\n";
	svg << "<text x=\"12\" y=\"" << top + 10 << "\">M / Mp (+-" << scene::jsonNumber(yMax) << ")</text>\n";
	svg << "<polyline fill=\"none\" stroke=\"#c03000\" stroke-width=\"1.2\" points=\"";
	const size_t stride = std::max<size_t>(1, r.hysteresis.size() / 4000);
	for (size_t i = 0; i < r.hysteresis.size(); i += stride)
	{
		std::snprintf(buf, sizeof buf, "%.1f,%.1f ", X(r.hysteresis[i].rotation_rad), Y(r.hysteresis[i].moment_nm / mp));
		svg << buf;
	}
	svg << "\"/>\n</svg>\n";
	return svg.str();
}
}  // namespace structures
