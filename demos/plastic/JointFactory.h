// One joint of any method between two bodies, from a section: the joint sits at a world pivot, with a world
// basis whose column 0 is the main bending axis (a hinge's axis), column 1 the other bending axis and column 2
// the member axis. Capacities and stiffnesses come from the section (Section.h); every method the thesis
// compares can be built the same way, so a scene does not know how each joint is configured.
#pragma once

#include <memory>
#include <string>

#include "Section.h"
#include "btBulletDynamicsCommon.h"

namespace plastic
{
enum class JointMethod
{
	HingeMotor,       // upstream btHingeConstraint, a motor at target 0 whose impulse is Mp * dt (stand-in)
	PlasticHinge,     // btPlasticHingeConstraint at Mp about the main bending axis
	ElasticPlastic,   // bt6DofElasticPlasticConstraint: every DOF at its capacity, rigid-plastic when too stiff
	ElasticPlastic2,  // bt6DofElasticPlastic2Constraint, the same on Spring2
};

// "hinge-motor", "plastic-hinge", "elastic-plastic", "elastic-plastic2"
const char* jointMethodName(JointMethod method);

struct JointSpec
{
	JointMethod method = JointMethod::PlasticHinge;
	btVector3 pivot_m{0, 0, 0};
	btMatrix3x3 basis = btMatrix3x3::getIdentity();  // world: bending axis 1 (hinge axis), bending axis 2, member axis
	SectionProperties section;
	Material material;
	double segment_length_m = 1.0;         // centre-to-centre of the bodies it joins: the elastic stiffness' length
	double max_plastic_rotation_rad = 1e9; // accumulated plastic rotation that breaks it
};

// The joint between a and b (b may be a static body). The hinge-motor stand-in's impulse follows the step:
// call updateJointForStep before each step for it; the other methods need nothing.
std::unique_ptr<btTypedConstraint> makeJoint(const JointSpec& spec, btRigidBody& a, btRigidBody& b);
void updateJointForStep(btTypedConstraint& joint, const JointSpec& spec, double step_s);

// Plastic work the joint has booked, J, and its plastic rotation, rad (0 for the hinge-motor stand-in, whose
// work is not booked by the joint).
double jointPlasticWork_j(const btTypedConstraint& joint);
double jointPlasticRotation_rad(const btTypedConstraint& joint);
}  // namespace plastic
