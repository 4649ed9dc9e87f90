#include "WreckingBallOutput.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "scene/JsonNumber.h"

namespace game
{
std::string toJson(const WreckingBallParameters& p, const WreckingBallResult& r)
{
	std::ostringstream o;
	o << "{\"scene\":\"wrecking-ball\",\"method\":\"" << plastic::jointMethodName(p.method) << "\",\"solver\":\"" << plastic::solverKindName(p.solver.solver)
	  << "\",\"iterations\":" << p.solver.iterations << ",\"internal_step_s\":" << scene::jsonNumber(p.solver.internal_step_s) << ",\"frame_rate_hz\":" << scene::jsonNumber(p.frame_rate_hz)
	  << ",\"plastic_moment_Nm\":" << scene::jsonNumber(r.estimate.plastic_moment_nm) << ",\"max_plastic_rotation_rad\":" << scene::jsonNumber(p.max_plastic_rotation_rad)
	  << ",\"release_energy_J\":" << scene::jsonNumber(r.estimate.release_energy_j) << ",\"estimated_impact_speed_m_s\":" << scene::jsonNumber(r.estimate.impact_speed_m_s)
	  << ",\"impact_kinetic_J\":" << scene::jsonNumber(r.impact_kinetic_j) << ",\"impact_speed_m_s\":" << scene::jsonNumber(r.impact_speed_m_s)
	  << ",\"gravity_work_J\":" << scene::jsonNumber(r.gravity_work_j) << ",\"kinetic_J\":" << scene::jsonNumber(r.kinetic_j) << ",\"elastic_J\":" << scene::jsonNumber(r.elastic_j)
	  << ",\"plastic_booked_J\":" << scene::jsonNumber(r.plastic_booked_j) << ",\"plastic_measured_J\":" << scene::jsonNumber(r.plastic_measured_j)
	  << ",\"dissipated_J\":" << scene::jsonNumber(r.dissipated_j) << ",\"max_energy_gain_J\":" << scene::jsonNumber(r.max_energy_gain_j) << ",\"yielded_joints\":" << r.yielded_joints
	  << ",\"broken_joints\":" << r.broken_joints << ",\"broken\":[";
	bool first = true;
	for (const FrameJointResult& j : r.joints)
		if (j.broken)
		{
			o << (first ? "" : ",") << "\"" << j.name << "\"";
			first = false;
		}
	o << "],\"joints\":[";
	for (size_t i = 0; i < r.joints.size(); i++)
	{
		const FrameJointResult& j = r.joints[i];
		o << (i ? "," : "") << "{\"name\":\"" << j.name << "\",\"booked_rotation_rad\":" << scene::jsonNumber(j.booked_rotation_rad)
		  << ",\"measured_rotation_rad\":" << scene::jsonNumber(j.measured_rotation_rad) << ",\"booked_work_J\":" << scene::jsonNumber(j.booked_work_j)
		  << ",\"measured_work_J\":" << scene::jsonNumber(j.measured_work_j) << ",\"broken\":" << (j.broken ? "true" : "false") << ",\"broken_at_s\":" << scene::jsonNumber(j.broken_at_s) << "}";
	}
	o << "],\"frames\":" << r.frames << ",\"internal_steps\":" << r.internal_steps << ",\"simulated_s\":" << scene::jsonNumber(r.simulated_s) << ",\"wall_s\":" << scene::jsonNumber(r.wall_s)
	  << ",\"real_time_factor\":" << scene::jsonNumber(r.real_time_factor) << ",\"max_frame_wall_ms\":" << scene::jsonNumber(1e3 * r.max_frame_wall_s)
	  << ",\"solver_fallbacks\":" << r.solver_fallbacks << ",\"finite\":" << (r.finite ? "true" : "false") << "}";
	return o.str();
}

std::string toSummary(const WreckingBallParameters& p, const WreckingBallResult& r)
{
	std::ostringstream o;
	o << "wrecking ball, " << plastic::jointMethodName(p.method) << ", " << plastic::solverKindName(p.solver.solver) << ", " << p.solver.iterations << " iterations, internal step "
	  << p.solver.internal_step_s << " s, " << p.frame_rate_hz << " Hz frames: " << r.frames << " frames, " << r.internal_steps << " internal steps, "
	  << r.simulated_s << " s simulated in " << r.wall_s << " s (real-time factor " << r.real_time_factor << ", slowest frame " << 1e3 * r.max_frame_wall_s
	  << " ms)\n";
	o << "  ball released with " << r.estimate.release_energy_j << " J (estimate " << r.estimate.impact_speed_m_s << " m/s at the bottom); impact "
	  << r.impact_kinetic_j << " J measured (" << r.impact_speed_m_s << " m/s)\n";
	o << "  gravity work " << r.gravity_work_j << " J = kinetic " << r.kinetic_j << " J + elastic " << r.elastic_j << " J + plastic " << r.plastic_booked_j
	  << " J (booked; Mp x rotations " << r.plastic_measured_j << " J) + dissipated " << r.dissipated_j << " J; largest energy gain " << r.max_energy_gain_j << " J\n";
	o << "  Mp " << r.estimate.plastic_moment_nm << " N m; " << r.yielded_joints << " joints yielded, " << r.broken_joints << " broken:";
	for (const FrameJointResult& j : r.joints)
		if (j.booked_rotation_rad > 0 || j.broken) o << " " << j.name << " " << j.booked_rotation_rad << " rad" << (j.broken ? " (broken)" : "");
	o << "\n";
	return o.str();
}

std::string jointsCsv(const WreckingBallResult& r)
{
	std::ostringstream o;
	o << "joint,plastic_moment_Nm,booked_rotation_rad,measured_rotation_rad,booked_work_J,measured_work_J,broken,broken_at_s\n";
	for (const FrameJointResult& j : r.joints)
		o << j.name << "," << scene::jsonNumber(j.plastic_moment_nm) << "," << scene::jsonNumber(j.booked_rotation_rad) << "," << scene::jsonNumber(j.measured_rotation_rad) << "," << scene::jsonNumber(j.booked_work_j)
		  << "," << scene::jsonNumber(j.measured_work_j) << "," << (j.broken ? 1 : 0) << "," << scene::jsonNumber(j.broken_at_s) << "\n";
	return o.str();
}

std::string historyHeader() { return "time_s,gravity_work_J,kinetic_J,elastic_J,plastic_booked_J,plastic_measured_J,dissipated_J,yielded_joints,broken_joints\n"; }

std::string historyRow(double time_s, const WreckingBallResult& r)
{
	std::ostringstream o;
	o << scene::jsonNumber(time_s) << "," << scene::jsonNumber(r.gravity_work_j) << "," << scene::jsonNumber(r.kinetic_j) << "," << scene::jsonNumber(r.elastic_j) << "," << scene::jsonNumber(r.plastic_booked_j) << ","
	  << scene::jsonNumber(r.plastic_measured_j) << "," << scene::jsonNumber(r.dissipated_j) << "," << r.yielded_joints << "," << r.broken_joints << "\n";
	return o.str();
}
}  // namespace game
