#include "JitMember.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace plastic
{
namespace
{

// the frame of a constraint on body, in body's coordinates, and its setter; false for a constraint whose frames this
// does not know
bool constraintFrames(btTypedConstraint& c, btTransform*& frameA, btTransform*& frameB)
{
	switch (c.getConstraintType())
	{
		case HINGE_CONSTRAINT_TYPE:
			frameA = &static_cast<btHingeConstraint&>(c).getAFrame();
			frameB = &static_cast<btHingeConstraint&>(c).getBFrame();
			return true;
		case D6_CONSTRAINT_TYPE:
		case D6_SPRING_CONSTRAINT_TYPE:
			frameA = &static_cast<btGeneric6DofConstraint&>(c).getFrameOffsetA();
			frameB = &static_cast<btGeneric6DofConstraint&>(c).getFrameOffsetB();
			return true;
		case D6_SPRING_2_CONSTRAINT_TYPE:
			frameA = &static_cast<btGeneric6DofSpring2Constraint&>(c).getFrameOffsetA();
			frameB = &static_cast<btGeneric6DofSpring2Constraint&>(c).getFrameOffsetB();
			return true;
		default:
			return false;
	}
}

void setConstraintFrames(btTypedConstraint& c, const btTransform& frameA, const btTransform& frameB)
{
	switch (c.getConstraintType())
	{
		case HINGE_CONSTRAINT_TYPE:
			static_cast<btHingeConstraint&>(c).setFrames(frameA, frameB);
			break;
		case D6_CONSTRAINT_TYPE:
		case D6_SPRING_CONSTRAINT_TYPE:
			static_cast<btGeneric6DofConstraint&>(c).setFrames(frameA, frameB);
			break;
		case D6_SPRING_2_CONSTRAINT_TYPE:
			static_cast<btGeneric6DofSpring2Constraint&>(c).setFrames(frameA, frameB);
			break;
		default:
			break;
	}
}

// the body's world inertia tensor about its centre of mass
btMatrix3x3 worldInertia(const btRigidBody& body, const btVector3& localInertia)
{
	const btMatrix3x3& R = body.getCenterOfMassTransform().getBasis();
	return R.scaled(localInertia) * R.transpose();
}

// m (|r|^2 E - r r^T): a point mass's inertia about a point r away
btMatrix3x3 parallelAxis(btScalar mass, const btVector3& r)
{
	const btScalar r2 = r.length2();
	return btMatrix3x3(r2 - r.x() * r.x(), -r.x() * r.y(), -r.x() * r.z(), -r.y() * r.x(), r2 - r.y() * r.y(), -r.y() * r.z(), -r.z() * r.x(),
					   -r.z() * r.y(), r2 - r.z() * r.z()) *
		   mass;
}
}  // namespace


JitMember::JitMember(btDiscreteDynamicsWorld& world, const BeamSpec& spec, btRigidBody* support) : m_world(world), m_beam(world, spec, support), m_support(support)
{
	if (!m_beam.errors().empty()) return;
	btRigidBody& first = *m_beam.segments().front();
	m_segmentShape = first.getCollisionShape();
	m_segmentMass = btScalar(1) / first.getInvMass();
	const btVector3& invInertia = first.getInvInertiaDiagLocal();
	m_segmentInertia = btVector3(btScalar(1) / invInertia.x(), btScalar(1) / invInertia.y(), btScalar(1) / invInertia.z());
	m_yieldEnergy_j = std::numeric_limits<double>::infinity();
	for (const JointSpec& j : m_beam.jointSpecs()) m_yieldEnergy_j = std::min(m_yieldEnergy_j, jointYieldEnergy_j(j));
	// a member without joints (one segment, free) has nothing to yield: it stays one body
	merge();
	m_merges = 0;
	m_mergeLoss_j = 0;
}

JitMember::~JitMember()
{
	// the beam takes its segments and joints out of the world: give the first segment back its own shape first
	if (m_whole) subdivide();
}

bool JitMember::isMemberBody(const btCollisionObject* object) const
{
	if (object == m_support) return true;
	const std::vector<btRigidBody*>& s = m_beam.segments();
	return std::find(s.begin(), s.end(), object) != s.end();
}

void JitMember::rebaseSupportJoint(const btTransform& from, const btTransform& to)
{
	// the joints on the first segment other than those inside the member (the support's): their frame on it, in its
	// coordinates, follows the change of its body frame, so that the frame stays where it is in the world
	btRigidBody& first = *m_beam.segments().front();
	for (int i = 0; i < first.getNumConstraintRefs(); i++)
	{
		btTypedConstraint& c = *first.getConstraintRef(i);
		btTransform *frameA = nullptr, *frameB = nullptr;
		if (isInnerJoint(&c) || !constraintFrames(c, frameA, frameB)) continue;
		const btTransform change = to.inverse() * from;
		btTransform a = *frameA, b = *frameB;
		if (&c.getRigidBodyA() == &first) a = change * a;
		if (&c.getRigidBodyB() == &first) b = change * b;
		setConstraintFrames(c, a, b);
	}
}

bool JitMember::isInnerJoint(const btTypedConstraint* c) const
{
	for (size_t j = m_support ? 1 : 0; j < m_beam.joints().size(); j++)
		if (m_beam.joints()[j].constraint.get() == c) return true;
	return false;
}

bool JitMember::mergeable() const
{
	if (m_whole || !m_beam.errors().empty()) return false;
	// a broken member is pieces, not one body
	for (const Joint& j : m_beam.joints())
		if (!j.constraint->isEnabled()) return false;
	// a joint from outside on a segment other than the first would lose its body while the member is whole
	const std::vector<btRigidBody*>& s = m_beam.segments();
	for (size_t i = 1; i < s.size(); i++)
		for (int k = 0; k < s[i]->getNumConstraintRefs(); k++)
			if (!isInnerJoint(s[i]->getConstraintRef(k))) return false;
	return true;
}

void JitMember::merge()
{
	if (!mergeable()) return;
	const std::vector<btRigidBody*>& segments = m_beam.segments();
	btRigidBody& first = *segments.front();
	// the segments' mass, centre of mass, momentum, kinetic energy
	btScalar mass = 0;
	btVector3 centre(0, 0, 0), momentum(0, 0, 0);
	double kinetic_j = 0;
	for (const btRigidBody* b : segments)
	{
		mass += m_segmentMass;
		centre += b->getCenterOfMassPosition() * m_segmentMass;
		momentum += b->getLinearVelocity() * m_segmentMass;
		const btVector3 w = b->getAngularVelocity();
		kinetic_j += 0.5 * double(m_segmentMass * b->getLinearVelocity().length2() + w.dot(worldInertia(*b, m_segmentInertia) * w));
	}
	centre /= mass;
	// their inertia and angular momentum about it
	btMatrix3x3 inertia(0, 0, 0, 0, 0, 0, 0, 0, 0);
	btVector3 angularMomentum(0, 0, 0);
	for (const btRigidBody* b : segments)
	{
		const btVector3 r = b->getCenterOfMassPosition() - centre;
		const btMatrix3x3 own = worldInertia(*b, m_segmentInertia);
		inertia = inertia + own + parallelAxis(m_segmentMass, r);
		angularMomentum += own * b->getAngularVelocity() + r.cross(b->getLinearVelocity() * m_segmentMass);
	}
	// the principal frame: inertia = R diag R^T
	btMatrix3x3 principal = inertia, R;
	principal.diagonalize(R, btScalar(1e-9), 100);
	const btVector3 diagonal(principal[0][0], principal[1][1], principal[2][2]);
	const btTransform whole(R, centre);
	const btVector3 velocity = momentum / mass;
	const btVector3 spin = R * ((R.transpose() * angularMomentum) / diagonal);
	// the shape: every segment's box where it is, in the whole body's frame
	m_wholeShape = std::make_unique<btCompoundShape>(true, int(segments.size()));
	m_local.clear();
	for (const btRigidBody* b : segments)
	{
		m_local.push_back(whole.inverseTimes(b->getCenterOfMassTransform()));
		m_wholeShape->addChildShape(m_local.back(), m_segmentShape);
	}
	// the segments and the inner joints leave the world; the first segment becomes the whole body
	for (size_t j = m_support ? 1 : 0; j < m_beam.joints().size(); j++) m_world.removeConstraint(m_beam.joints()[j].constraint.get());
	const bool asleep = std::all_of(segments.begin(), segments.end(), [](const btRigidBody* b)
									{ return b->getActivationState() == ISLAND_SLEEPING; });
	const btTransform firstBefore = first.getCenterOfMassTransform();
	m_filters.clear();
	for (btRigidBody* b : segments)
	{
		const btBroadphaseProxy* proxy = b->getBroadphaseHandle();
		m_filters.push_back({proxy->m_collisionFilterGroup, proxy->m_collisionFilterMask});
		m_world.removeRigidBody(b);
	}
	first.setCollisionShape(m_wholeShape.get());
	first.setMassProps(mass, diagonal);
	first.setCenterOfMassTransform(whole);
	first.setLinearVelocity(velocity);
	first.setAngularVelocity(spin);
	first.updateInertiaTensor();
	rebaseSupportJoint(firstBefore, whole);
	m_world.addRigidBody(&first, m_filters.front().first, m_filters.front().second);
	if (asleep) first.setActivationState(ISLAND_SLEEPING);
	const double after_j = 0.5 * double(mass * velocity.length2() + spin.dot(angularMomentum));
	m_mergeLoss_j += kinetic_j - after_j;
	m_whole = true;
	m_merges++;
}

void JitMember::subdivide()
{
	if (!m_whole) return;
	const std::vector<btRigidBody*>& segments = m_beam.segments();
	btRigidBody& first = *segments.front();
	const btTransform whole = first.getCenterOfMassTransform();
	const btVector3 velocity = first.getLinearVelocity(), spin = first.getAngularVelocity();
	m_world.removeRigidBody(&first);
	first.setCollisionShape(m_segmentShape);
	first.setMassProps(m_segmentMass, m_segmentInertia);
	for (size_t i = 0; i < segments.size(); i++)
	{
		btRigidBody& b = *segments[i];
		const btTransform t = whole * m_local[i];
		b.setCenterOfMassTransform(t);
		b.setLinearVelocity(velocity + spin.cross(t.getOrigin() - whole.getOrigin()));
		b.setAngularVelocity(spin);
		b.updateInertiaTensor();
	}
	rebaseSupportJoint(whole, first.getCenterOfMassTransform());
	for (size_t i = 0; i < segments.size(); i++)
	{
		m_world.addRigidBody(segments[i], m_filters[i].first, m_filters[i].second);
		segments[i]->activate(true);
	}
	for (size_t j = m_support ? 1 : 0; j < m_beam.joints().size(); j++) m_world.addConstraint(m_beam.joints()[j].constraint.get(), true);
	m_wholeShape.reset();
	m_whole = false;
	m_subdivisions++;
}

bool JitMember::subdivideIfThreatened(double lookahead_s)
{
	if (!m_whole) return false;
	btRigidBody& body = *wholeBody();
	btVector3 minimum, maximum;
	body.getAabb(minimum, maximum);
	const btScalar mass = btScalar(1) / body.getInvMass();
	bool threatened = false;
	const btCollisionObjectArray& objects = m_world.getCollisionObjectArray();
	for (int i = 0; i < objects.size() && !threatened; i++)
	{
		const btCollisionObject* object = objects[i];
		if (object == &body || isMemberBody(object)) continue;
		const btRigidBody* other = btRigidBody::upcast(object);
		const btVector3 otherVelocity = other ? other->getLinearVelocity() : btVector3(0, 0, 0);
		const btVector3 relative = otherVelocity - body.getLinearVelocity();
		// the member's own spin moves its far points too: the fastest point of its box
		const btScalar spinReach = body.getAngularVelocity().length() * (maximum - minimum).length() / 2;
		const btScalar speed = relative.length() + spinReach;
		btVector3 otherMin, otherMax;
		object->getCollisionShape()->getAabb(object->getWorldTransform(), otherMin, otherMax);
		const btVector3 reach(speed * btScalar(lookahead_s), speed * btScalar(lookahead_s), speed * btScalar(lookahead_s));
		if (!TestAabbAgainstAabb2(minimum - reach, maximum + reach, otherMin, otherMax)) continue;
		// the mass that meets the member: a kinematic body's is unbounded; against a free member the reduced mass of the
		// two; against a supported one the other body's own (the support takes what the member does not)
		const bool otherMoves = other && other->getInvMass() > 0;
		if (other && other->isKinematicObject() && speed > 0)
		{
			threatened = true;
			continue;
		}
		double mass_kg = double(mass);
		if (otherMoves) mass_kg = m_support ? 1.0 / double(other->getInvMass()) : double(mass) / (1 + double(mass * other->getInvMass()));
		if (0.5 * mass_kg * double(speed) * double(speed) > m_yieldEnergy_j) threatened = true;
	}
	if (threatened) subdivide();
	return threatened;
}

bool JitMember::mergeIfAtRest()
{
	if (m_whole) return false;
	const std::vector<btRigidBody*>& s = m_beam.segments();
	if (!mergeable() || !std::all_of(s.begin(), s.end(), [](const btRigidBody* b)
									 { return b->getActivationState() == ISLAND_SLEEPING; }))
		return false;
	merge();
	return m_whole;
}
}  // namespace plastic
