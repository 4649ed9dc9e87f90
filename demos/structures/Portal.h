// A fixed-base portal frame: two columns of height h at x = 0 and x = L, a beam of span L between their tops,
// every member in segments of one section, every joint (bases, knees, inner joints) a plastic joint of one
// method, in the x-y plane bending about z. Loads, proportional to one factor lambda: H along +x at the left
// knee and V along -y at mid-span. Plastic analysis: the beam (V L/2 = 4 Mp), sway (H h = 4 Mp) and combined
// (H h + V L/2 = 6 Mp) mechanisms; the collapse factor is the least over every combination of the two
// independent mechanisms, computed from the parameters.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "scene/SteppedScene.h"
#include "scene/RectangularMember.h"
#include "scene/StructureRig.h"
#include "CollapseTest.h"

namespace structures
{
// the member: its section and material; the collapse test's ramp
struct PortalParameters : scene::RectangularMember, CollapseRamp
{
	scene::SolverSettings solver;
	double span_m = 4.0;
	double height_m = 3.0;
	int column_segments = 2;  // the joints between them are the mid-column hinge sites
	int beam_segments = 2;    // even: a joint at mid-span
	double horizontal_load_n = 50e3;  // H at lambda = 1: H h = 3 Mp with the defaults
	double vertical_load_n = 75e3;    // V at lambda = 1: V L / 2 = 3 Mp: the combined mechanism at lambda = 1
	// the load factor rises by the ramp (CollapseRamp) at ramp_rate_per_s from slow_from_fraction of the collapse
	// factor on; 0: no ramp, the load factor is load_factor from the start (a hold below collapse: does the frame creep?)
	double ramp_rate_per_s = 0.02;
	double load_factor = 0.9;
	double duration_s = 60.0;  // at most
	// gravity: a dead load down at each knee (N), raised from 0 over knee_load_ramp_s and then held (with the ramp,
	// the load factor starts rising then); its work P times the knees' descent is the P-delta effect of a sway
	double knee_load_n = 0;
	double knee_load_ramp_s = 1.0;
	// not empty: a sway pushover instead of H and V: an actuator (a stiff spring and damper along x on the left knee,
	// with integral action) drives the knee through these drifts (of h, in order) at drift_rate_per_s once the knee
	// loads are on, then holds the last settle_s; sway_load_ratios in the result are its force H h / (4 Mp) over the
	// last 0.002 of drift before each is reached (a loading branch)
	std::vector<double> sway_drifts;
	double drift_rate_per_s = 0.02;
	double settle_s = 1.0;
};

// The frame's joints in order along it: base-left, the left column's inner joints, knee-left, the beam's inner
// joints (mid-span among them), knee-right, the right column's inner joints, base-right.
struct PortalJointSite
{
	std::string name;          // base-left, column-left-1.., knee-left, beam-1.., mid-span, knee-right, column-right-1.., base-right
	double beam_rotation = 0;  // in the beam mechanism per unit rotation of its members (counter-clockwise +)
	double sway_rotation = 0;  // in the sway mechanism
};

struct PortalAnswer
{
	double plastic_moment_nm = 0;
	std::vector<PortalJointSite> sites;
	double beam_factor = 0;                   // 4 Mp / (V L / 2) (infinite without V)
	double sway_factor = 0;                   // 4 Mp / (H h)
	double combined_factor = 0;               // 6 Mp / (H h + V L / 2)
	double collapse_factor = 0;               // the least over every mechanism
	std::string mechanism;                    // beam, sway, combined (or combination)
	std::vector<double> mechanism_rotations;  // per site, in the collapse mechanism, the largest = 1
	std::vector<int> mechanism_sites;         // the sites that rotate in it
};

// The sway mechanism of a rigid-plastic frame turned so far that the knees have moved by drift x h along x: with the
// knee loads P (2 knee_load_n in all) its equilibrium H h cos(theta) + P h sin(theta) = 4 Mp (the four hinges at Mp,
// h sin(theta) = drift h) gives H h / (4 Mp) = (1 - P h drift / (4 Mp)) / sqrt(1 - drift^2); without P it is the
// lever's 1 / cos(theta), and a first-order analysis says 1 at every drift.
double swaySecondOrderRatio(const PortalParameters& p, double drift);

struct PortalResult : scene::RunStats
{
	PortalAnswer answer;
	double collapse_factor = 0;  // the load factor when the collapse was seen (NaN: never)
	double collapse_error_pct = 0;
	std::vector<double> rotations_rad;            // per site at the end, from the bodies
	double max_rotation_rad = 0;                  // largest |site rotation| over the run
	double creep_rad = 0;                         // largest change of a site's rotation over the last two thirds of the run
	std::vector<double> mechanism_rotations_rad;  // per site since the collapse was seen
	std::vector<int> mechanism_sites;             // the sites that turned >= 20 % of the largest since then
	bool mechanism_matches = false;
	double load_work_j = 0;
	double kinetic_j = 0;
	double booked_plastic_work_j = 0;
	// Mp x sum |site rotation| from the bodies: the plastic work of rigid-plastic joints; an elastic joint's rotation
	// holds its spring's too (patch 0047 makes the elastic-plastic joints springs at fine steps)
	double geometric_plastic_work_j = 0;
	double elastic_j = 0;  // the elastic energy the joints' springs hold at the end
	// (load work - kinetic - booked plastic work - elastic) / load work
	double energy_balance_error_pct = 0;
	std::vector<double> sway_load_ratios;        // sway pushover: H h / (4 Mp) before each of sway_drifts
	std::vector<double> sway_measured_drifts;    // and the left knee's drift then
	std::vector<double> second_order_load_ratios;  // swaySecondOrderRatio at each measured drift
	int holds = 0;                        // ramp: how many times the load was held (more than one: softening or vibration was not a collapse)
};

std::vector<std::string> validatePortalParameters(const PortalParameters& p);
PortalAnswer portalAnswer(const PortalParameters& p);
// The scene, built from its parameters, one internal step at a time (the runner and the browser example both use it).
class PortalScene : public scene::SteppedScene
{
public:
	explicit PortalScene(const PortalParameters& p);
	~PortalScene() override;
	SCENE_STEPPED_SCENE_OVERRIDES;
	PortalResult result() const;  // measured now

private:
	struct State;
	std::unique_ptr<State> m;
};

// PortalScene stepped until it is done.
PortalResult runPortal(const PortalParameters& p);
}  // namespace structures
