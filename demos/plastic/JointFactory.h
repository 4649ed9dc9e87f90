// One joint of any method between two bodies, from a section: the joint sits at a world pivot, with a world
// basis whose column 0 is the main bending axis (a hinge's axis), column 1 the other bending axis and column 2
// the member axis. Capacities and stiffnesses come from the section (Section.h); every method the thesis
// compares can be built the same way, so a scene does not know how each joint is configured.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "Section.h"
#include "StressStrain.h"
#include "SolverSettings.h"
#include "btBulletDynamicsCommon.h"

namespace plastic
{
enum class JointMethod
{
	Brittle,          // upstream btGeneric6DofConstraint locked in every DOF, breaking at breaking_force_n (thesis 2.3)
	Spring,           // upstream btGeneric6DofSpringConstraint: linear DOFs locked, bending and torsion springs of Mp per rad
	Spring2,          // the same on upstream btGeneric6DofSpring2Constraint (stiffness limited as upstream users get it)
	HingeMotor,       // upstream btHingeConstraint, a motor at target 0 whose impulse is Mp * dt (stand-in)
	PlasticHinge,     // btPlasticHingeConstraint at Mp about the main bending axis
	ElasticPlastic,   // bt6DofElasticPlasticConstraint: every DOF at its capacity, rigid-plastic when too stiff
	ElasticPlastic2,  // bt6DofElasticPlastic2Constraint, the same on Spring2
};

// "brittle", "spring", "spring2", "hinge-motor", "plastic-hinge", "elastic-plastic", "elastic-plastic2"
const char* jointMethodName(JointMethod method);

// Which of an elastic-plastic2 joint's DOFs yield together (bt6DofElasticPlastic2Constraint::setYieldSurface)
enum class YieldSurface
{
	PerDof,   // each DOF at its own capacity (the default)
	Biaxial,       // the two bending moments on the section's BiaxialInteraction curve
	BendingAxial,    // the main bending moment (about y) and the axial force on the section's AxialInteraction curve
	BendingTorsion,  // the main bending moment (about y) and the torque on the section's TorsionInteraction curve
};

// Low-cycle fatigue (patch 0030): the joint also breaks when Miner's sum over the half-cycles of its plastic rotation
// reaches 1 under Coffin-Manson, eps_p / 2 = eps_f (2 N)^c, where eps_p is the plastic strain of the main bending's
// extreme fibre: the plastic rotation over the hinge length times half the depth. The joint's rotation coefficient is
// theta_f = 2 Lp eps_f / depth (fatigueDuctilityRotation_rad).
struct LowCycleFatigue
{
	double ductility_coefficient = 0.5;  // eps_f' (strain), > 0
	double ductility_exponent = -0.6;    // c, in [-1, -0.1]
	double hinge_length_m = 0.01;        // Lp: the length of member whose plastic curvature the joint's rotation stands for, > 0
};

// Manson's method of universal slopes (1965): the plastic part of its strain range, D^0.6 N^-0.6 with the ductility
// D = ln(1 / (1 - reduction of area)), is Coffin-Manson with c = -0.6 and eps_f = 2^-0.4 D^0.6. For a material
// without measured constants; reduction_of_area in (0, 1).
LowCycleFatigue universalSlopesFatigue(double reduction_of_area, double hinge_length_m);

struct JointSpec
{
	JointMethod method = JointMethod::PlasticHinge;
	btVector3 pivot_m{0, 0, 0};
	btMatrix3x3 basis = btMatrix3x3::getIdentity();  // world: bending axis 1 (hinge axis), bending axis 2, member axis
	// the section and material the capacities and stiffnesses come from (and, in a BeamBuilder, the segments' box and
	// mass), unless they are given directly below
	SectionProperties section;
	Material material;
	// given directly (a game's own numbers, N and N m), instead of capacities(section, material); a capacity of
	// SIMD_INFINITY leaves that DOF rigid
	std::optional<SectionCapacities> capacities;
	// given directly for this joint's segment (N/m, N m/rad), instead of stiffness(section, material, segment length)
	std::optional<SegmentStiffness> stiffness;
	double segment_length_m = 1.0;         // centre-to-centre of the bodies it joins: the elastic stiffness' length
	double max_plastic_rotation_rad = 1e9; // accumulated plastic rotation that breaks it
	double min_steps_per_period = 25.0;    // elastic-plastic: steps per natural period below which a DOF is rigid-plastic
	double breaking_force_n = 0;           // brittle: the force (N) at which it breaks (impulse threshold = force x step)
	JointSolverSettings solver;            // what the joint asks of the solver (default: warm started rows)
	YieldSurface yield_surface = YieldSurface::PerDof;  // elastic-plastic2 only
	// elastic-plastic2 only: the main bending (about y) hardens as the section does under this curve (HingeLaw.h: the
	// section's moment-curvature as parallel layers, the hinge length segment_length_m); its elastic stiffness and
	// first yield come from the curve, the other DOFs keep the material's. Without it the joint is elastic-perfectly
	// plastic at fy W_pl. In a step in which the DOF is rigid-plastic (too stiff for the step) it yields at fy W_pl.
	std::optional<StressStrainCurve> stress_strain;
	// the plastic methods: breaking by low-cycle fatigue beside max_plastic_rotation_rad (none: by rotation alone)
	std::optional<LowCycleFatigue> fatigue;
};

// theta_f of spec.fatigue for the joint's section (2 Lp eps_f / depth), rad; 0 without fatigue
double fatigueDuctilityRotation_rad(const JointSpec& spec);

// A joint and, for the plastic methods, its plastic bookkeeping (the same interface for all three classes, kept
// when the joint is made, so nothing has to find out later which class a joint is). The hinge-motor stand-in has
// none: its work is not booked by the joint.
struct Joint
{
	std::unique_ptr<btTypedConstraint> constraint;
	const btPlasticConstraintState* plasticState = nullptr;
	JointMethod method = JointMethod::PlasticHinge;

	double plasticWork_j() const { return plasticState ? plasticState->getAbsorbedEnergy() : 0.0; }
	// the plastic classes' elastic energy, or the springs' 1/2 k x^2 of the upstream spring methods; 0 once broken
	double elasticEnergy_j() const;
	double plasticRotation_rad() const { return plasticState ? plasticState->getCurrentPlasticRotation() : 0.0; }
};

// The joint's capacities and stiffnesses: the ones given directly, or the section's of the material.
SectionCapacities jointCapacities(const JointSpec& spec);
SegmentStiffness jointStiffness(const JointSpec& spec);
// The least work that can yield a joint of the spec: the elastic energy its spring holds when a DOF reaches its capacity,
// cap^2 / (2 k), over the DOFs (bending about both axes, torsion, axial, shear), with the section's stiffness over the
// joint's segment length (J), from an unloaded joint. It is the member's: an elastic-plastic joint whose springs are
// elastic at the step cannot yield under less. It is not a bound for what the model books where it is rigid-plastic (a
// plastic hinge, an elastic-plastic DOF too stiff for the step: they yield under any blow whose impulse over a step
// passes the cap), nor for a joint that is loaded already, hardens from below fy W_pl, breaks by force, or yields on a
// surface of two DOFs: there just in time misses what such a joint would book under a smaller blow.
double jointYieldEnergy_j(const JointSpec& spec);

// A message per field of the spec that is out of its range (naming the field and its range; the section's error and
// the solver settings' included); empty when makeJoint can make the joint.
std::vector<std::string> validate(const JointSpec& spec);

// The joint between a and b (b may be a static body); a Joint without a constraint when validate(spec) is not empty.
// The hinge-motor stand-in's impulse and the brittle joint's breaking impulse follow the step: call updateJointForStep
// before each step; the other methods need nothing.
Joint makeJoint(const JointSpec& spec, btRigidBody& a, btRigidBody& b);
void updateJointForStep(btTypedConstraint& joint, const JointSpec& spec, double step_s);
}  // namespace plastic
