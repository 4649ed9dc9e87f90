// A cantilever: a straight member of length L along +x from a fixed support, in n segments, bending about z,
// loaded at its tip by P along -y, either fixed in direction (dead) or turning with the tip (follower).
// Plastic analysis: it collapses at P = Mp / L with the hinge at the support, the inner joints locked (their
// moments are below the root's). Under a constant dead load P = lambda Mp / L (lambda > 1) it turns about the
// root and stops where the load's work equals the plastic work, P L sin(theta) = Mp theta.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "scene/SteppedScene.h"
#include "scene/RectangularMember.h"
#include "scene/StructureRig.h"
#include "CollapseTest.h"
#include "plastic/StressStrain.h"

namespace structures
{
// the member: its section (width along the bending axis z, depth along y) and material; the collapse test's ramp
struct CantileverParameters : scene::RectangularMember, CollapseRamp
{
	scene::SolverSettings solver;
	double length_m = 2.0;
	int segments = 4;
	bool follower_load = false;
	// ramp_rate_per_s > 0: the load ratio P L / Mp rises by the ramp (CollapseRamp, the load factor being P L / Mp);
	// 0: the load ratio is load_ratio from the start.
	double load_ratio = 1.5;
	double ramp_rate_per_s = 0;
	double duration_s = 30.0;  // at most; a constant dead load stops when the beam has stopped
	// elastic-plastic2 only: the joints harden as the section does under this curve (JointSpec::stress_strain; its
	// first pair sets E and fy, and Mp = fy W_pl); none: elastic-perfectly plastic at --fy
	std::optional<plastic::StressStrainCurve> stress_strain;
	// > 0: a pushover under displacement control instead of a load: an actuator (a stiff spring and damper on the tip's
	// end, along y, with integral action) drives the tip down to tip_drift x L at drift_rate_per_s and holds it
	// settle_s; the load ratio is its force P L / Mp over the last 0.002 of drift (0.1 s at most) before it reaches the
	// drift (a loading branch: a rigid-plastic hinge held still carries any moment up to its cap), reported with the
	// drift the tip had then
	double tip_drift = 0;
	// not empty (with tip_drift 0): a cyclic pushover, the actuator's target driven through these drifts in order
	// (negative: up) at drift_rate_per_s, then held settle_s; the load ratio is measured before each, as above
	std::vector<double> cyclic_drifts;
	double drift_rate_per_s = 0.02;
	double settle_s = 1.0;
	// the support's joint stands for half a segment (BeamSpec::support_joint_half_length)
	bool support_joint_half_length = false;
};

struct CantileverAnswer
{
	double plastic_moment_nm = 0;
	double collapse_load_n = 0;    // Mp / L
	double collapse_ratio = 1;     // P L / Mp at collapse
	double stop_rotation_rad = 0;  // constant dead load: where lambda sin(theta) = theta; 0 if it holds; NaN (follower, lambda > 1): never
};

struct CantileverResult : scene::RunStats
{
	CantileverAnswer answer;
	double collapse_ratio = 0;     // ramp: the load ratio when the collapse was seen (NaN: never)
	std::vector<int> mechanism;    // ramp: the joints (0 = root) that turned >= 20 % of the largest rotation after it
	double root_rotation_rad = 0;  // at the end, measured from the bodies (positive: the tip went down)
	double max_root_rotation_rad = 0;
	double max_inner_rotation_rad = 0;    // largest |rotation| of any inner joint over the run, from the bodies
	double creep_rad = 0;                 // largest change of a joint's rotation over the last two thirds of the run
	double stop_rotation_rad = 0;         // root rotation when the beam stopped (constant dead load; NaN: it did not)
	double load_work_j = 0;               // the load times its point's displacement
	double kinetic_j = 0;                 // from the bodies' velocities, at the end
	double geometric_plastic_work_j = 0;  // Mp x the sum of |joint rotations| measured from the bodies
	double booked_plastic_work_j = 0;     // what the joints booked (0 for the hinge-motor stand-in)
	double energy_balance_error_pct = 0;  // (load work - kinetic - geometric plastic work) / load work
	int holds = 0;                        // ramp: how many times the load was held (more than one: softening or vibration was not a collapse)
	double measured_tip_drift = 0;        // pushover: the tip's downward displacement / L, over the same window
	double drift_load_ratio = 0;          // pushover: the actuator's force P L / Mp over the last 0.002 of drift
	std::vector<double> cyclic_load_ratios;     // cyclic: the same before each of cyclic_drifts (P down positive)
	std::vector<double> cyclic_measured_drifts; // and the tip's drift then
};

std::vector<std::string> validateCantileverParameters(const CantileverParameters& p);
CantileverAnswer cantileverAnswer(const CantileverParameters& p);
// The scene, built from its parameters, one internal step at a time (the runner and the browser example both use it).
class CantileverScene : public scene::SteppedScene
{
public:
	explicit CantileverScene(const CantileverParameters& p);
	~CantileverScene() override;
	SCENE_STEPPED_SCENE_OVERRIDES;
	CantileverResult result() const;  // measured now

private:
	struct State;
	std::unique_ptr<State> m;
};

// CantileverScene stepped until it is done.
CantileverResult runCantilever(const CantileverParameters& p);
}  // namespace structures
