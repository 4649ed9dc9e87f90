#include "WreckingBallOutput.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace game
{
namespace
{
std::string num(double value)
{
	if (!std::isfinite(value)) return "null";
	char text[64];
	std::snprintf(text, sizeof text, "%.9g", value);
	return text;
}

}  // namespace

std::string toJson(const WreckingBallParameters& p, const WreckingBallResult& r)
{
	std::ostringstream o;
	o << "{\"scene\":\"wrecking-ball\",\"method\":\"" << plastic::jointMethodName(p.method) << "\",\"solver\":\"" << plastic::solverKindName(p.solver.solver)
	  << "\",\"iterations\":" << p.solver.iterations << ",\"internal_step_s\":" << num(p.solver.internal_step_s) << ",\"frame_rate_hz\":" << num(p.frame_rate_hz)
	  << ",\"plastic_moment_Nm\":" << num(r.estimate.plastic_moment_nm) << ",\"max_plastic_rotation_rad\":" << num(p.max_plastic_rotation_rad)
	  << ",\"release_energy_J\":" << num(r.estimate.release_energy_j) << ",\"estimated_impact_speed_m_s\":" << num(r.estimate.impact_speed_m_s)
	  << ",\"impact_kinetic_J\":" << num(r.impact_kinetic_j) << ",\"impact_speed_m_s\":" << num(r.impact_speed_m_s)
	  << ",\"gravity_work_J\":" << num(r.gravity_work_j) << ",\"kinetic_J\":" << num(r.kinetic_j) << ",\"elastic_J\":" << num(r.elastic_j)
	  << ",\"plastic_booked_J\":" << num(r.plastic_booked_j) << ",\"plastic_measured_J\":" << num(r.plastic_measured_j)
	  << ",\"dissipated_J\":" << num(r.dissipated_j) << ",\"max_energy_gain_J\":" << num(r.max_energy_gain_j) << ",\"yielded_joints\":" << r.yielded_joints
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
		o << (i ? "," : "") << "{\"name\":\"" << j.name << "\",\"booked_rotation_rad\":" << num(j.booked_rotation_rad)
		  << ",\"measured_rotation_rad\":" << num(j.measured_rotation_rad) << ",\"booked_work_J\":" << num(j.booked_work_j)
		  << ",\"measured_work_J\":" << num(j.measured_work_j) << ",\"broken\":" << (j.broken ? "true" : "false") << ",\"broken_at_s\":" << num(j.broken_at_s) << "}";
	}
	o << "],\"frames\":" << r.frames << ",\"internal_steps\":" << r.internal_steps << ",\"simulated_s\":" << num(r.simulated_s) << ",\"wall_s\":" << num(r.wall_s)
	  << ",\"real_time_factor\":" << num(r.real_time_factor) << ",\"max_frame_wall_ms\":" << num(1e3 * r.max_frame_wall_s)
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
		o << j.name << "," << num(j.plastic_moment_nm) << "," << num(j.booked_rotation_rad) << "," << num(j.measured_rotation_rad) << "," << num(j.booked_work_j)
		  << "," << num(j.measured_work_j) << "," << (j.broken ? 1 : 0) << "," << num(j.broken_at_s) << "\n";
	return o.str();
}

std::string historyHeader() { return "time_s,gravity_work_J,kinetic_J,elastic_J,plastic_booked_J,plastic_measured_J,dissipated_J,yielded_joints,broken_joints\n"; }

std::string historyRow(double time_s, const WreckingBallResult& r)
{
	std::ostringstream o;
	o << num(time_s) << "," << num(r.gravity_work_j) << "," << num(r.kinetic_j) << "," << num(r.elastic_j) << "," << num(r.plastic_booked_j) << ","
	  << num(r.plastic_measured_j) << "," << num(r.dissipated_j) << "," << r.yielded_joints << "," << r.broken_joints << "\n";
	return o.str();
}
}  // namespace game
