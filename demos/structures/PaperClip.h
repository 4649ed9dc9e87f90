// A paper clip: a steel wire held in a vise (the ground) with one leg bent back and forth through +-A by a hand, a
// kinematic body turning about the joint's axis, theta(t) = A sin(2 pi t / T), whose rotation is locked to the leg's
// (the hand leaves the leg's position to the joint). The wire's joint at the vise is a plastic joint of the round
// bar's section that breaks by low-cycle fatigue (JointSpec::fatigue). Answer: a rigid-plastic joint's plastic
// rotation is the driven rotation, so its half-cycles have ranges A, 2A, 2A, ...; Coffin-Manson and Miner's rule give
// the time the damage reaches 1 (cycles = that time / T). A joint with an elastic range flows less and lasts longer.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "plastic/JointFactory.h"
#include "scene/SteppedScene.h"
#include "scene/StructureRig.h"

namespace structures
{
struct PaperClipParameters
{
	scene::SolverSettings solver;
	double wire_diameter_m = 1.0e-3;
	double leg_length_m = 0.03;
	double yield_stress_pa = 400e6;
	double youngs_modulus_pa = 200e9;
	double density_kg_m3 = 7800;
	double bend_amplitude_rad = 0.785398;  // A: 45 degrees each way
	double cycle_period_s = 1.0;           // T
	// Coffin-Manson by Manson's universal slopes from the wire's reduction of area (c = -0.6), over a hinge of
	// hinge_length_m: the length a bend by hand makes plastic, about two wire diameters
	double reduction_of_area = 0.6;
	double hinge_length_m = 2.0e-3;
	double duration_s = 30.0;  // at most; the run ends when the wire breaks
};

struct PaperClipAnswer
{
	double plastic_moment_nm = 0;         // fy d^3 / 6
	double ductility_rotation_rad = 0;    // theta_f = 2 Lp eps_f / d
	double ductility_exponent = -0.6;     // c
	double break_time_s = 0;              // rigid-plastic: when Miner's sum reaches 1 (infinity: not within 1e6 cycles)
	double cycles_to_break = 0;           // break_time_s / T
	double constant_amplitude_cycles = 0; // N of Coffin-Manson at a plastic strain amplitude of A d / (2 Lp)
};

// one sample of the hysteresis: the joint's rotation (from the bodies) and the hand's moment on the leg about the axis
struct HysteresisSample
{
	double time_s = 0;
	double rotation_rad = 0;
	double moment_nm = 0;
};

struct PaperClipResult : scene::RunStats
{
	PaperClipAnswer answer;
	bool broken = false;
	double break_time_s = 0;       // when the joint broke (NaN: it did not)
	double cycles_to_break = 0;    // break_time_s / T
	double fatigue_damage = 0;     // the joint's, at the end (or when it broke)
	double plastic_rotation_rad = 0;  // booked, accumulated |flow|
	double plastic_work_j = 0;     // booked
	double hand_work_j = 0;        // the hand's moment times its own rotation, summed over the steps
	double kinetic_j = 0;          // the leg's, at the end
	double start_kinetic_j = 0;    // the leg's at the start (it starts turning with the hand)
	double elastic_j = 0;          // held by the joint at the end
	double energy_balance_error_pct = 0;  // (hand's work - plastic - elastic - kinetic change) / hand's work
	double peak_moment_nm = 0;     // largest |moment| the hand applied
	std::vector<HysteresisSample> hysteresis;  // every step until it broke
};

std::vector<std::string> validatePaperClipParameters(const PaperClipParameters& p);
PaperClipAnswer paperClipAnswer(const PaperClipParameters& p);
// the wire's joint (the toolkit's spec: round bar, the method, fatigue) at the vise, bending about z
plastic::JointSpec paperClipJointSpec(const PaperClipParameters& p);

class PaperClipScene : public scene::SteppedScene
{
public:
	explicit PaperClipScene(const PaperClipParameters& p);
	~PaperClipScene() override;
	SCENE_STEPPED_SCENE_OVERRIDES;
	PaperClipResult result() const;

private:
	struct State;
	std::unique_ptr<State> m;
};

PaperClipResult runPaperClip(const PaperClipParameters& p);
}  // namespace structures
