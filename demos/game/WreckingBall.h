// The game scene: a steel portal frame of plastic members (toolkit I sections and joints, fixed to the ground) hit
// in its plane by a wrecking ball on a chain, at 60 Hz frames with the toolkit's game solver settings (SolverSettings.h:
// four internal steps per frame, 10 iterations). The frame bends at its plastic joints, keeps its shape and breaks
// where a joint passes its plastic rotation limit. Everything the result reports is measured from the bodies (the
// energies, the joints' rotations) beside what the joints booked; nothing in the scene acts on the bodies but gravity,
// contacts and the constraints.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "plastic/JointFactory.h"
#include "plastic/SolverSettings.h"
#include "scene/SteppedScene.h"
#include "Pendulum.h"
#include "SteelFrame.h"

namespace game
{
// The toolkit's game defaults (btDirectJointSolver, 10 iterations, 1/240 s): the frame's closed loops need no setting.
plastic::WorldSolverSettings wreckingBallSolverSettings();

struct WreckingBallParameters
{
	plastic::JointMethod method = plastic::JointMethod::PlasticHinge;
	plastic::WorldSolverSettings solver = wreckingBallSolverSettings();
	double frame_rate_hz = 60;
	double duration_s = 3.0;
	double gravity_m_s2 = 9.81;
	// the frame, in the x-y plane: bays + 1 column lines at x = 0, span_m, .., storeys storeys of height_m, a beam of
	// every bay at every floor; each member in segments, joined to the others at the nodes (the top segment of a
	// column's storey). One storey and one bay (the default) is a fixed-base portal frame.
	int storeys = 1;
	int bays = 1;
	double span_m = 4.0;
	double height_m = 3.0;
	int column_segments = 4;  // the joints between segments are where the members can bend
	int beam_segments = 4;
	// an I section bending about its strong axis (about world z): roughly an IPE 200 without root fillets
	double section_depth_m = 0.2;
	double flange_width_m = 0.1;
	double web_thickness_m = 0.0056;
	double flange_thickness_m = 0.0085;
	double yield_stress_pa = 355e6;
	double youngs_modulus_pa = 210e9;
	double density_kg_m3 = 7850;
	double max_plastic_rotation_rad = 0.2;  // accumulated plastic rotation that breaks a joint
	// the wrecking ball: a sphere on a chain of links from a fixed pivot, released from rest at release_angle_rad
	// from the vertical, away from the frame; at the bottom of its swing it touches the left column at impact_height_m
	double ball_mass_kg = 2000;
	double ball_radius_m = 0.4;
	double chain_length_m = 5.0;  // pivot to the ball's surface
	int chain_links = 8;
	double chain_mass_kg = 80;
	double release_angle_rad = 1.0;
	double impact_height_m = 1.5;
	double ball_friction = 0.5;
};

// "name: value is not in [low, high] unit" for every parameter out of its range
std::vector<std::string> validateWreckingBallParameters(const WreckingBallParameters& p);
// the frame of the parameters (its segments may not sleep: the figures were made so; the city lets them) standing at
// origin_m, and the ball's pendulum that hits it: released away from it (towards -x), at the bottom of its swing 2 cm from
// its left column at the impact height
SteelFrameSpec steelFrameSpec(const WreckingBallParameters& p, const btVector3& origin_m = btVector3(0, 0, 0));
PendulumSpec pendulumSpec(const WreckingBallParameters& p, const btVector3& origin_m = btVector3(0, 0, 0));

struct WreckingBallEstimate
{
	double plastic_moment_nm = 0;
	double release_energy_j = 0;  // potential energy the ball and chain give up from the release to the bottom
	double impact_speed_m_s = 0;  // of the ball at the bottom, from the release energy (chain and ball swinging as one)
};
WreckingBallEstimate wreckingBallEstimate(const WreckingBallParameters& p);

// One plastic joint of the frame after a run.
struct FrameJointResult
{
	// a portal: base-left, column-left-1.., knee-left, beam-1.., knee-right, column-right-1.., base-right; more storeys
	// or bays: base-C, column-C-K-J (column line C from 0, storey K from 1, joint J of the member from its foot),
	// beam-K-B-J (floor K, bay B from 1, J from the left node; -end at the right node)
	std::string name;
	double plastic_moment_nm = 0;
	double booked_rotation_rad = 0;    // accumulated plastic rotation the joint booked (0: hinge-motor stand-in)
	double measured_rotation_rad = 0;  // its rotation measured from the bodies (at the step it broke, if it broke)
	double booked_work_j = 0;
	double measured_work_j = 0;  // Mp x |measured rotation|, up to max_plastic_rotation_rad for a broken joint
	bool broken = false;
	double broken_at_s = -1;  // -1: not broken
};

struct WreckingBallResult : scene::RunStats  // wall_s: stepping only (not building)
{
	WreckingBallEstimate estimate;
	std::vector<FrameJointResult> joints;
	double impact_kinetic_j = 0;  // ball and chain, measured before the first step in which a contact of the ball pushed the frame (0: none)
	double impact_speed_m_s = 0;  // of the ball's centre, then
	double gravity_work_j = 0;    // potential energy given up, from the bodies' heights
	double kinetic_j = 0;         // every moving body, at the end
	double elastic_j = 0;         // stored in elastic joints, at the end
	double plastic_booked_j = 0;
	double plastic_measured_j = 0;  // sum of the joints' measured work
	double max_energy_gain_j = 0;   // largest (kinetic + elastic + booked plastic) - (initial kinetic + gravity work) over the frames
	double dissipated_j = 0;        // (initial kinetic + gravity work) - (kinetic + elastic + booked plastic) at the end: contacts, solver
	int yielded_joints = 0;
	int broken_joints = 0;
	long frames = 0;
	double real_time_factor = 0;  // simulated_s / wall_s
	double max_frame_wall_s = 0;
};

// The scene, one 60 Hz frame per step() (each frame: the solver settings' internal steps).
class WreckingBallScene : public scene::SteppedScene
{
public:
	explicit WreckingBallScene(const WreckingBallParameters& p);  // throws std::invalid_argument naming a bad parameter
	~WreckingBallScene() override;
	SCENE_STEPPED_SCENE_OVERRIDES;
	WreckingBallResult result() const;  // measured now
	const btRigidBody& ball() const;
	std::vector<const btRigidBody*> frameBodies() const;
	std::vector<const btRigidBody*> chainBodies() const;
	const WreckingBallParameters& parameters() const;

private:
	struct State;
	std::unique_ptr<State> m;
};

// WreckingBallScene stepped until it is done.
WreckingBallResult runWreckingBall(const WreckingBallParameters& p);
}  // namespace game
