#include "CharpyRun.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "CharpyScene.h"
#include "CharpyVerdict.h"
#include "scene/JsonNumber.h"

CharpyResult runCharpy(const CharpyParameters& parameters, std::ostream* history)
{
	const auto start = std::chrono::steady_clock::now();
	CharpyScene scene(parameters);
	CharpyResult r;
	r.method = std::string(charpyMethodName(parameters.method));
	r.joints_book_work = charpyMethodBooksJointWork(parameters.method);
	r.dt_s = parameters.dt_s;
	r.auto_dt = parameters.auto_dt;
	r.iterations = parameters.solver_iterations;
	r.solver = plastic::solverKindName(parameters.solver);
	r.speculative_contacts = parameters.speculative_contacts;
	r.box_edges_across_faces = scene.world().getDispatchInfo().m_boxBoxEdgesAcrossFaces;  // as the world has it
	r.contact_turn_prediction = scene.world().getSolverInfo().m_contactTurnPrediction;
	r.E0_J = scene.initialEnergy_j();
	r.analytic_J = scene.section().analytic_loss_j;
	r.theta_pass_rad = scene.section().theta_pass_rad;
	r.plastic_moment_Nm = scene.section().plastic_moment_nm;
	r.impact_speed_m_s = scene.impactSpeed_m_s();
	r.friction = parameters.friction;
	r.warning = charpySelfLockWarning(parameters);
	r.step_warning = scene.speculativeReachWarning();
	r.striker_radius_m = parameters.striker_radius_m;
	r.anvil_radius_m = parameters.anvil_radius_m;
	r.anvil_taper_rad = parameters.anvil_taper_rad;
	if (history)
	{
		*history << "time_s,potential_J,kinetic_J,elastic_J,total_J,plastic_work_J,bend_angle_rad,hammer_angle_rad\n";
	}
	double maxBend = 0;
	bool passed = false;
	int historySteps = 0;
	while (!scene.done() && !(parameters.end_when_clear && (scene.endedClear() || scene.clear())))
	{
		scene.step();
		r.frames++;
		// the frame's end, or where the test ended within it (the world's own steps run on to the frame's end)
		const CharpyEndState state = scene.endState();
		if (!state.broken) maxBend = std::max(maxBend, state.end_bend_angle_rad);  // folded while whole
		if (!passed && scene.passedAnvils())
		{
			passed = true;
			r.pass_end_bend_angle_rad = state.end_bend_angle_rad;
			r.pass_plastic_rotation_rad = state.plastic_rotation_rad;
		}
		// a row per frame that moved the world: a frame shorter than a contact substep may step nothing (the world
		// owes it to the next frame), and a row that repeats its time would say time stood still
		if (history && scene.internalSteps() != historySteps)
		{
			historySteps = scene.internalSteps();
			CharpyEnergies e = scene.energies();
			char line[256];
			std::snprintf(line, sizeof line, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", scene.time_s(), e.potential_j, e.kinetic_j,
						  e.elastic_j, e.total_j, scene.plasticWork_j(), scene.bendAngle_rad(), scene.hammerAngle_rad());
			*history << line;
		}
	}
	// where the test ended (the world's steps may have run on to the frame's end; CharpyScene::endState)
	const CharpyEndState end = scene.endState();
	r.end_time_s = end.time_s;
	r.kinetic_against_hammer_J = end.kinetic_against_hammer_j;
	r.internal_steps = scene.internalSteps();
	r.test_steps = end.internal_steps;
	r.solver_fallbacks = scene.solverFallbacks();
	r.finite = scene.finite();
	r.E_end_J = end.energies.total_j;
	r.energy_loss_J = r.E0_J - r.E_end_J;
	r.plastic_work_J = end.plastic_work_j;
	r.other_loss_J = r.energy_loss_J - r.plastic_work_J;
	r.error_pct = 100.0 * (r.energy_loss_J - r.analytic_J) / r.analytic_J;
	r.plastic_rotation_rad = end.plastic_rotation_rad;
	r.bend_angle_rad = end.bend_angle_rad;
	r.end_bend_angle_rad = end.end_bend_angle_rad;
	r.max_energy_gain_J = scene.maxEnergyGain_j();
	r.max_booked_excess_J = scene.maxBookedExcess_j();
	r.max_penetration_m = scene.maxPenetration_m();
	r.max_speed_m_s = scene.maxSpeed_m_s();
	r.max_distance_m = scene.maxDistance_m();
	r.hammer_angle_end_rad = end.hammer_angle_rad;
	r.broken = end.broken;
	r.passed_anvils = scene.passedAnvils();
	r.over_the_top = scene.overTheTop();
	// Folded at mid-span into a V, the specimen fits between the anvils only once its halves span less than the gap:
	// bend >= 2 acos(gap / length). An unbroken specimen that got past them with less bend went through the anvils.
	r.max_bend_rad = maxBend;
	r.specimen_width_m = parameters.specimen_width_m;
	r.min_pass_bend_rad = 2.0 * std::acos(std::min(1.0, parameters.anvil_gap_m / parameters.specimen_length_m));
	r.tunnelled = r.passed_anvils && !r.broken && maxBend < r.min_pass_bend_rad;
	r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	return r;
}

std::string toJson(const CharpyResult& r)
{
	std::ostringstream out;
	auto flag = [](bool b) { return b ? "true" : "false"; };
	out << "{\"method\":\"" << r.method << "\",\"dt\":" << scene::jsonNumber(r.dt_s) << ",\"auto_dt\":" << flag(r.auto_dt)
		<< ",\"iterations\":" << r.iterations << ",\"solver\":\"" << r.solver << "\",\"solver_fallbacks\":" << r.solver_fallbacks << ",\"speculative_contacts\":" << flag(r.speculative_contacts) << ",\"box_edges_across_faces\":" << flag(r.box_edges_across_faces) << ",\"contact_turn_prediction\":" << flag(r.contact_turn_prediction) << ",\"steps\":" << r.internal_steps << ",\"test_steps\":" << r.test_steps << ",\"frames\":" << r.frames << ",\"end_time_s\":" << scene::jsonNumber(r.end_time_s) << ",\"kinetic_against_hammer_J\":" << scene::jsonNumber(r.kinetic_against_hammer_J)
		<< ",\"wall_s\":" << scene::jsonNumber(r.wall_s) << ",\"E0_J\":" << scene::jsonNumber(r.E0_J) << ",\"E_end_J\":" << scene::jsonNumber(r.E_end_J)
		<< ",\"energy_loss_J\":" << scene::jsonNumber(r.energy_loss_J) << ",\"plastic_work_J\":" << scene::jsonNumber(r.plastic_work_J)
		<< ",\"other_loss_J\":" << scene::jsonNumber(r.other_loss_J) << ",\"analytic_J\":" << scene::jsonNumber(r.analytic_J)
		<< ",\"theta_pass_rad\":" << scene::jsonNumber(r.theta_pass_rad) << ",\"plastic_moment_Nm\":" << scene::jsonNumber(r.plastic_moment_Nm)
		<< ",\"error_pct\":" << scene::jsonNumber(r.error_pct) << ",\"plastic_rotation_rad\":" << scene::jsonNumber(r.plastic_rotation_rad)
		<< ",\"bend_angle_rad\":" << scene::jsonNumber(r.bend_angle_rad)
		<< ",\"end_bend_angle_rad\":" << scene::jsonNumber(r.end_bend_angle_rad) << ",\"pass_end_bend_angle_rad\":" << scene::jsonNumber(r.pass_end_bend_angle_rad)
		<< ",\"pass_plastic_rotation_rad\":" << scene::jsonNumber(r.pass_plastic_rotation_rad) << ",\"impact_speed_m_s\":" << scene::jsonNumber(r.impact_speed_m_s)
		<< ",\"friction\":" << scene::jsonNumber(r.friction) << ",\"striker_radius_m\":" << scene::jsonNumber(r.striker_radius_m)
		<< ",\"anvil_edge_radius_m\":" << scene::jsonNumber(r.anvil_radius_m) << ",\"anvil_taper_rad\":" << scene::jsonNumber(r.anvil_taper_rad)
		<< ",\"broken\":" << flag(r.broken) << ",\"passed_anvils\":" << flag(r.passed_anvils) << ",\"over_the_top\":" << flag(r.over_the_top)
		<< ",\"max_bend_rad\":" << scene::jsonNumber(r.max_bend_rad) << ",\"tunnelled\":" << flag(r.tunnelled) << ",\"finite\":" << flag(r.finite)
		<< ",\"max_energy_gain_J\":" << scene::jsonNumber(r.max_energy_gain_J) << ",\"max_booked_excess_J\":" << scene::jsonNumber(r.max_booked_excess_J) << ",\"max_penetration_m\":" << scene::jsonNumber(r.max_penetration_m)
		<< ",\"max_speed_m_s\":" << scene::jsonNumber(r.max_speed_m_s) << ",\"max_distance_m\":" << scene::jsonNumber(r.max_distance_m)
		<< ",\"hammer_angle_end_rad\":" << scene::jsonNumber(r.hammer_angle_end_rad);
	std::string why;
	const CharpyVerdict verdict = classifyCharpyRun(r, &why);
	std::string accuracyWhy;
	const CharpyAccuracy accuracy = classifyCharpyAccuracy(r, &accuracyWhy);
	if (!r.warning.empty())
	{
		accuracyWhy += (accuracyWhy.empty() ? "" : "; ") + std::string("predicted before the run: ") + r.warning;
	}
	out << ",\"verdict\":\"" << charpyVerdictName(verdict) << "\",\"verdict_reason\":\"" << why << "\""
		<< ",\"accuracy\":\"" << charpyAccuracyName(accuracy) << "\",\"accuracy_reason\":\"" << accuracyWhy << "\""
		<< ",\"self_locking\":" << flag(!r.warning.empty()) << ",\"warning\":\"" << r.warning << "\""
		<< ",\"closes_past_reach\":" << flag(!r.step_warning.empty()) << ",\"step_warning\":\"" << r.step_warning << "\"}";
	return out.str();
}

std::string toSummary(const CharpyResult& r)
{
	char text[1024];
	std::snprintf(text, sizeof text,
				  "Charpy impact test, method %s, dt %g s%s, %d iterations, solver %s%s: %ld internal steps to %.2f ms in %.3f s wall time\n"
				  "  hammer energy E0 %.2f J, impact speed %.3f m/s\n"
				  "  energy loss %.2f J (plastic work %.2f J, other %.2f J); analytic Mp * theta_pass = %.2f N m * %.4f rad = %.2f J; error %+.2f %%\n"
				  "  plastic rotation %.3f rad, broken %s, passed anvils %s%s, max energy gain %.3g J, plastic work booked beyond the loss %.3g J, max penetration %.3g m%s\n",
				  r.method.c_str(), r.dt_s, r.auto_dt ? " (auto)" : "", r.iterations, r.solver.c_str(), r.speculative_contacts ? ", speculative contacts" : "", r.internal_steps, 1000.0 * r.end_time_s, r.wall_s, r.E0_J,
				  r.impact_speed_m_s, r.energy_loss_J, r.plastic_work_J, r.other_loss_J, r.plastic_moment_Nm, r.theta_pass_rad,
				  r.analytic_J, r.error_pct, r.plastic_rotation_rad, r.broken ? "yes" : "no", r.passed_anvils ? "yes" : "no",
				  r.tunnelled ? " (TUNNELLED: past the anvils with too little bend to fit the gap)" : "", r.max_energy_gain_J, r.max_booked_excess_J, r.max_penetration_m,
				  r.finite ? "" : "\n  NOT FINITE: the simulation produced NaN or infinity");
	std::string summary = text;
	if (!r.warning.empty())
	{
		summary += "  SELF-LOCKING (predicted before the run): " + r.warning + "\n";
	}
	if (!r.step_warning.empty())
	{
		summary += "  STEP PAST THE CONTACTS' REACH (predicted before the run): " + r.step_warning + "\n";
	}
	return summary;
}
