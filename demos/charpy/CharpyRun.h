// Runs a Charpy scene to its duration and summarises the energy balance.
#pragma once

#include <ostream>
#include <string>

#include "CharpyParameters.h"

struct CharpyResult
{
	std::string method;
	double dt_s = 0;
	bool auto_dt = false;
	int iterations = 0;
	std::string solver;        // plastic::solverKindName of the parameters' solver
	int solver_fallbacks = 0;  // internal steps in which a direct or MLCP solver fell back to sequential impulse
	bool speculative_contacts = false;  // the parameters' speculative_contacts
	bool box_edges_across_faces = false;  // whether the world clips edges across faces (box_edges_across_faces or speculative_contacts)
	bool contact_turn_prediction = false;  // whether the world's contact rows predict turns (contact_turn_prediction or world steps)
	long frames = 0;
	long internal_steps = 0;
	// of those, the ones up to the end of the test (the step that left the specimen clear): fewer where the world's
	// contact stepping stepped on to the frame's end after it
	long test_steps = 0;
	double kinetic_against_hammer_J = 0;  // CharpyScene::kineticAgainstHammer_j at the end
	double end_time_s = 0;  // simulated time at the end: the duration, or when the specimen was clear (end_when_clear)
	double wall_s = 0;
	double E0_J = 0;
	double E_end_J = 0;
	double energy_loss_J = 0;
	double plastic_work_J = 0;
	double other_loss_J = 0;  // energy_loss - plastic_work: contacts, friction, solver
	double analytic_J = 0;
	double theta_pass_rad = 0;
	double plastic_moment_Nm = 0;
	double error_pct = 0;     // (energy_loss - analytic) / analytic
	double plastic_rotation_rad = 0;
	double bend_angle_rad = 0;
	double impact_speed_m_s = 0;
	double friction = 0;  // combined Coulomb coefficient of the specimen contacts
	std::string warning;  // charpySelfLockWarning of the parameters: predicted before the run
	std::string step_warning;  // CharpyScene::speculativeReachWarning: predicted before the run
	double striker_radius_m = 0;  // 0 = the thesis' flat nose
	double anvil_radius_m = 0;    // 0 = sharp anvil edges
	double anvil_taper_rad = 0;   // taper of the gap behind rounded edges
	double max_energy_gain_J = 0;
	double max_booked_excess_J = 0;  // CharpyScene::maxBookedExcess_j: plastic work booked beyond the energy lost
	double max_penetration_m = 0;
	double end_bend_angle_rad = 0;  // rotation of the last part relative to the first at the end, about any axis
	// the same, and plastic_rotation_rad, at the end of the frame in which every part first got behind the anvils (0
	// when they never did): after it a chain flying in long steps can drift at its joints
	double pass_end_bend_angle_rad = 0;
	double pass_plastic_rotation_rad = 0;
	double max_speed_m_s = 0;       // fastest dynamic body over the run
	double max_distance_m = 0;      // farthest dynamic body centre from the origin over the run
	double hammer_angle_end_rad = 0;  // pendulum angle from the impact position at the end (< 0: swung on past it)
	bool broken = false;
	bool passed_anvils = false;
	bool over_the_top = false;  // passed, but a part went over the anvils instead of through the gap
	double specimen_width_m = 0;
	double max_bend_rad = 0;        // largest end-to-end bend while the specimen was whole
	double min_pass_bend_rad = 0;   // the bend below which the unbroken specimen cannot fit between the anvils
	bool tunnelled = false;   // unbroken, past the anvils with less than min_pass_bend_rad: through penetration
	bool joints_book_work = false;  // plastic_work_J is what the joints did at their cap (methods 6-8)
	bool finite = true;
};

// history: if not null, receives the per-frame CSV time history (with a header line).
CharpyResult runCharpy(const CharpyParameters& parameters, std::ostream* history = nullptr);

// One JSON object on one line.
std::string toJson(const CharpyResult& result);
// Human-readable summary, several lines.
std::string toSummary(const CharpyResult& result);
