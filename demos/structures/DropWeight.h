// A drop weight: a heavy ball (mass G, no gravity, moving at v0 along -y) strikes the middle of a beam of span L
// along x, in an even number of segments bending about z, either simply supported (a pin at the left end, a roller
// at the right) or clamped (plastic joints of the method at both ends, the right one on a carriage that slides
// along x: bending only, no membrane force, as in the rigid-plastic estimate). Rigid-plastic estimate: the impact
// is perfectly plastic, the ball and the two halves (each turning about its support) move as one mechanism, so the
// kinetic energy after the impact is G / (G + m_eff) of the ball's, m_eff = 8 I_half / L^2 (m / 3 for a uniform
// beam); it all goes into the hinges: Mp x 2 theta (simply supported: the mid-span hinge turns 2 theta) or
// Mp x (theta + 2 theta + theta) (clamped), theta the rotation of each half.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "scene/SteppedScene.h"
#include "scene/RectangularMember.h"
#include "scene/StructureRig.h"

namespace structures
{
// the member: its section and material
struct DropWeightParameters : scene::RectangularMember
{
	scene::SolverSettings solver;
	bool clamped = false;
	double span_m = 2.0;
	int segments = 2;  // even: a joint at mid-span
	double weight_mass_kg = 1000;
	double weight_radius_m = 0.05;
	double impact_speed_m_s = 4.5;
	double duration_s = 2.0;  // at most; the run ends when the beam has stopped
	bool run_to_duration = false;  // true: it runs on to duration_s after the beam has stopped
};

struct DropWeightAnswer
{
	double plastic_moment_nm = 0;
	double beam_mass_kg = 0;
	double effective_mass_kg = 0;       // of the two halves at mid-span, 8 I_half / L^2
	double initial_kinetic_j = 0;       // G v0^2 / 2
	double kinetic_after_impact_j = 0;  // G / (G + m_eff) of it
	double half_rotation_rad = 0;       // theta
	double midspan_rotation_rad = 0;    // 2 theta
	double support_rotation_rad = 0;    // theta (plastic only when clamped)
};

struct DropWeightResult : scene::RunStats
{
	DropWeightAnswer answer;
	// all bodies' kinetic energy when the ball and the mid-span first move together, plus the joints' booked plastic work
	// and elastic energy then (NaN: never)
	double kinetic_after_impact_j = 0;
	double midspan_rotation_rad = 0;    // at the end, from the bodies (positive: the middle went down)
	double left_support_rotation_rad = 0;
	double right_support_rotation_rad = 0;
	double max_inner_rotation_rad = 0;  // largest |rotation| of the other inner joints at the end (0 with 2 segments)
	double kinetic_end_j = 0;
	// Mp x sum |rotation| of the plastic joints, from the bodies: their plastic work if they are rigid-plastic; an elastic
	// joint's rotation holds its spring's too (Mp / k, 0.06 rad for elastic-plastic at 1/3840 s)
	double geometric_plastic_work_j = 0;
	double booked_plastic_work_j = 0;
	double elastic_end_j = 0;           // the elastic energy the joints' springs hold at the end
	double midspan_error_pct = 0;       // against the estimate
	double plastic_work_error_pct = 0;  // geometric plastic work against the estimate of the kinetic energy after impact
	// (energy after impact - kinetic at the end - booked plastic work - elastic at the end) / energy after impact
	double balance_error_pct = 0;
};

std::vector<std::string> validateDropWeightParameters(const DropWeightParameters& p);
DropWeightAnswer dropWeightAnswer(const DropWeightParameters& p);
// The scene, built from its parameters, one internal step at a time (the runner and the browser example both use it).
class DropWeightScene : public scene::SteppedScene
{
public:
	explicit DropWeightScene(const DropWeightParameters& p);
	~DropWeightScene() override;
	SCENE_STEPPED_SCENE_OVERRIDES;
	DropWeightResult result() const;  // measured now
	const btRigidBody& ball() const;

private:
	struct State;
	std::unique_ptr<State> m;
};

// DropWeightScene stepped until it is done.
DropWeightResult runDropWeight(const DropWeightParameters& p);
}  // namespace structures
