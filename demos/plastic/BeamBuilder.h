// A straight member from A to B in n rigid segments joined by joints of one method (JointFactory), its
// start optionally fixed to a support by the same kind of joint. The Beam owns its bodies and joints and takes
// them out of the world when it is destroyed.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "JointFactory.h"

namespace plastic
{
struct BeamSpec
{
	btVector3 start_m{0, 0, 0};
	btVector3 end_m{1, 0, 0};
	int segments = 4;
	btVector3 bending_axis{0, 0, 1};  // world axis of the main bending (a hinge's axis), across the member
	// Bullet's deactivation for the segments, as for any body: they fall asleep once the member has been at rest for
	// gDeactivationTime (a yielding joint keeps them awake), and a contact or an active neighbour wakes them. false:
	// DISABLE_DEACTIVATION, for a scene whose loads change on resting bodies (a load ramp: a force on a sleeping
	// body does nothing and does not wake it)
	bool may_sleep = true;
	// the joint at the support stands for the half segment between the support and the first segment's centre: its
	// elastic stiffness is E I / (L / 2) and its hinge length L / 2 (a member whose joints each stand for the length
	// around them; its elastic tip deflection converges as the segments get shorter: +3.1 % at 4, +0.8 % at 8). false:
	// a whole segment, as the scenes have been built (+41 % at 4 segments, +9.6 % at 16)
	bool support_joint_half_length = false;
	// every joint of the member (and its support): method, section, material (or capacities and stiffnesses given
	// directly), limits, solver settings, yield surface; the beam sets each one's pivot, basis and segment length. The
	// segments' boxes and masses come from its section and material, which a beam always needs.
	JointSpec joint;
};

// A message per field of the spec that is out of its range (its joint's fields included); empty when a Beam can be
// built from it.
std::vector<std::string> validate(const BeamSpec& spec);

class Beam
{
public:
	// support: a static body the start is fixed to (its joint is the first one), or nullptr for a free start. A spec
	// that validate refuses builds nothing (no bodies, no joints): errors() says why.
	Beam(btDiscreteDynamicsWorld& world, const BeamSpec& spec, btRigidBody* support);
	~Beam();
	Beam(const Beam&) = delete;
	Beam& operator=(const Beam&) = delete;

	const std::vector<btRigidBody*>& segments() const { return m_segments; }
	const std::vector<Joint>& joints() const { return m_joints; }  // from the start to the end
	const std::vector<JointSpec>& jointSpecs() const { return m_specs; }
	double segmentLength_m() const { return m_segmentLength_m; }
	const std::vector<std::string>& errors() const { return m_errors; }  // validate(spec): empty for a beam that was built
	double plasticWork_j() const;
	// call before each step: the hinge-motor stand-in's impulse follows the step
	void updateForStep(double step_s);

private:
	void removeFromWorld();  // the joints and segments added so far

	btDiscreteDynamicsWorld& m_world;
	double m_segmentLength_m;
	std::unique_ptr<btCollisionShape> m_shape;
	std::vector<std::unique_ptr<btRigidBody>> m_bodies;
	std::vector<btRigidBody*> m_segments;
	std::vector<Joint> m_joints;
	std::vector<JointSpec> m_specs;
	std::vector<std::string> m_errors;
};
}  // namespace plastic
