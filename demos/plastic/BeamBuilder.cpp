#include "BeamBuilder.h"

#include <string>

namespace plastic
{
namespace
{
// the member's axis and its main bending axis across it; false when there is none
bool memberAxes(const BeamSpec& spec, btVector3& axis, btVector3& bending)
{
	const btVector3 member = spec.end_m - spec.start_m;
	if (!(member.length() > 0)) return false;
	axis = member / member.length();
	bending = spec.bending_axis - axis * spec.bending_axis.dot(axis);
	return bending.length() > 1e-6;
}
}  // namespace

std::vector<std::string> validate(const BeamSpec& spec)
{
	std::vector<std::string> errors;
	if (spec.segments < 1 || spec.segments > 10000)
	{
		errors.push_back("segments: " + std::to_string(spec.segments) + " is not in [1, 10000]");
	}
	btVector3 axis, bending;
	if (!((spec.end_m - spec.start_m).length() > 0))
	{
		errors.push_back("end: the member from start to end has no length");
	}
	else if (!memberAxes(spec, axis, bending))
	{
		errors.push_back("bending axis: it must not be parallel to the member");
	}
	const SectionProperties& section = spec.joint.section;
	if (section.error.empty() && !(section.width_m > 0 && section.depth_m > 0 && section.area_m2 > 0))
	{
		errors.push_back("joint.section: a beam's segments need a section (their box and mass), also when the joint's capacities are given");
	}
	// the joints' own fields; their segment length is the beam's, set by the beam
	JointSpec joint = spec.joint;
	if (errors.empty()) joint.segment_length_m = (spec.end_m - spec.start_m).length() / spec.segments;
	for (const std::string& e : validate(joint)) errors.push_back(e);
	return errors;
}

Beam::Beam(btDiscreteDynamicsWorld& world, const BeamSpec& spec, btRigidBody* support) : m_world(world), m_segmentLength_m(0), m_errors(validate(spec))
{
	btVector3 axis, bending;
	if (!m_errors.empty() || !memberAxes(spec, axis, bending))
	{
		return;  // refused: no bodies, no joints
	}
	const double length_m = (spec.end_m - spec.start_m).length();
	bending.normalize();
	const btVector3 other = axis.cross(bending);
	btMatrix3x3 basis;  // columns: bending axis 1, bending axis 2, member axis
	basis.setValue(bending.x(), other.x(), axis.x(), bending.y(), other.y(), axis.y(), bending.z(), other.z(), axis.z());
	m_segmentLength_m = length_m / spec.segments;
	// the segment box: depth (section z) across the main bending axis, width (section y) along it
	m_shape = std::make_unique<btBoxShape>(btVector3(btScalar(spec.joint.section.width_m / 2), btScalar(spec.joint.section.depth_m / 2), btScalar(m_segmentLength_m / 2)));
	const btScalar mass = btScalar(spec.joint.material.density_kg_m3 * spec.joint.section.area_m2 * m_segmentLength_m);
	btVector3 inertia;
	m_shape->calculateLocalInertia(mass, inertia);
	// the box's local x is bending axis 1, y bending axis 2, z the member
	btRigidBody* previous = support;
	for (int i = 0; i < spec.segments; i++)
	{
		btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, m_shape.get(), inertia);
		info.m_startWorldTransform = btTransform(basis, spec.start_m + axis * btScalar((i + 0.5) * m_segmentLength_m));
		m_bodies.push_back(std::make_unique<btRigidBody>(info));
		btRigidBody* body = m_bodies.back().get();
		if (!spec.may_sleep) body->setActivationState(DISABLE_DEACTIVATION);
		m_world.addRigidBody(body);
		m_segments.push_back(body);
		if (previous)
		{
			JointSpec joint = spec.joint;
			joint.pivot_m = spec.start_m + axis * btScalar(i * m_segmentLength_m);
			joint.basis = basis;
			joint.segment_length_m = (i == 0 && spec.support_joint_half_length) ? m_segmentLength_m / 2 : m_segmentLength_m;
			m_joints.push_back(makeJoint(joint, *previous, *body));  // validate(spec) checked its fields
			m_specs.push_back(joint);
			m_world.addConstraint(m_joints.back().constraint.get(), true);
		}
		previous = body;
	}
}

Beam::~Beam() { removeFromWorld(); }

void Beam::removeFromWorld()
{
	for (Joint& j : m_joints) m_world.removeConstraint(j.constraint.get());
	for (btRigidBody* b : m_segments) m_world.removeRigidBody(b);
}

double Beam::plasticWork_j() const
{
	double w = 0;
	for (const Joint& j : m_joints) w += j.plasticWork_j();
	return w;
}

void Beam::updateForStep(double step_s)
{
	for (size_t i = 0; i < m_joints.size(); i++) updateJointForStep(*m_joints[i].constraint, m_specs[i], step_s);
}
}  // namespace plastic
