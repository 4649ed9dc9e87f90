#include "JitStructure.h"

#include <algorithm>
#include <unordered_map>

namespace plastic
{
namespace
{
bool hasConstraintRef(btRigidBody& body, const btTypedConstraint* c)
{
	for (int i = 0; i < body.getNumConstraintRefs(); i++)
		if (body.getConstraintRef(i) == c) return true;
	return false;
}
}  // namespace

JitStructure::JitStructure(btDiscreteDynamicsWorld& world, std::vector<btRigidBody*> bodies, std::vector<btTypedConstraint*> joints, double yieldEnergy_j)
	: m_world(world), m_bodies(std::move(bodies)), m_joints(std::move(joints)), m_yieldEnergy_j(yieldEnergy_j)
{
	for (btTypedConstraint* c : m_joints) m_jointsDisableCollisions.push_back(hasConstraintRef(c->getRigidBodyA(), c));
	for (const btRigidBody* b : m_bodies)
	{
		Saved s;
		s.mass = b->getInvMass() > 0 ? btScalar(1) / b->getInvMass() : btScalar(0);
		const btVector3& inv = b->getInvInertiaDiagLocal();
		s.inertia = btVector3(inv.x() > 0 ? 1 / inv.x() : 0, inv.y() > 0 ? 1 / inv.y() : 0, inv.z() > 0 ? 1 / inv.z() : 0);
		const btBroadphaseProxy* proxy = b->getBroadphaseHandle();
		s.group = proxy ? proxy->m_collisionFilterGroup : int(btBroadphaseProxy::DefaultFilter);
		s.mask = proxy ? proxy->m_collisionFilterMask : int(btBroadphaseProxy::AllFilter);
		m_saved.push_back(s);
	}
}

JitStructure::~JitStructure()
{
	if (m_whole) subdivide();
}

void JitStructure::merge()
{
	if (m_whole) return;
	m_wholeShape = std::make_unique<btCompoundShape>(true, int(m_bodies.size()));
	for (size_t i = 0; i < m_bodies.size(); i++)
	{
		btRigidBody& b = *m_bodies[i];
		const btScalar mass = m_saved[i].mass;
		const btVector3 v = b.getLinearVelocity(), w = b.getAngularVelocity();
		const btMatrix3x3& R = b.getCenterOfMassTransform().getBasis();
		m_mergeLoss_j += 0.5 * double(mass * v.length2() + w.dot(R.scaled(m_saved[i].inertia) * (R.transpose() * w)));
		m_wholeShape->addChildShape(b.getCenterOfMassTransform(), b.getCollisionShape());
	}
	for (btTypedConstraint* c : m_joints) m_world.removeConstraint(c);
	for (btRigidBody* b : m_bodies)
	{
		m_world.removeRigidBody(b);
		// static out of the world: a joint from a body that stays in the world holds to it as to a fixed body (as
		// btTypedConstraint::getFixedBody does), and the island manager must not take it for a body of an island
		b->setLinearVelocity(btVector3(0, 0, 0));
		b->setAngularVelocity(btVector3(0, 0, 0));
		b->setMassProps(0, btVector3(0, 0, 0));
		b->updateInertiaTensor();
		b->setIslandTag(-1);
		b->setCompanionId(-1);
	}
	btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, m_wholeShape.get());
	if (!m_bodies.empty())
	{
		info.m_friction = m_bodies.front()->getFriction();
		info.m_restitution = m_bodies.front()->getRestitution();
		info.m_rollingFriction = m_bodies.front()->getRollingFriction();
	}
	m_wholeBody = std::make_unique<btRigidBody>(info);
	// with its bodies' collision filter, so that it meets what they would
	if (m_saved.empty())
		m_world.addRigidBody(m_wholeBody.get());
	else
		m_world.addRigidBody(m_wholeBody.get(), m_saved.front().group, m_saved.front().mask);
	m_whole = true;
	m_merges++;
}

void JitStructure::subdivide()
{
	if (!m_whole) return;
	m_world.removeRigidBody(m_wholeBody.get());
	m_wholeBody.reset();
	m_wholeShape.reset();
	for (size_t i = 0; i < m_bodies.size(); i++)
	{
		btRigidBody& b = *m_bodies[i];
		b.setMassProps(m_saved[i].mass, m_saved[i].inertia);
		b.updateInertiaTensor();
		b.setLinearVelocity(btVector3(0, 0, 0));
		b.setAngularVelocity(btVector3(0, 0, 0));
		m_world.addRigidBody(&b, m_saved[i].group, m_saved[i].mask);
		b.activate(true);
	}
	for (size_t j = 0; j < m_joints.size(); j++) m_world.addConstraint(m_joints[j], m_jointsDisableCollisions[j]);
	m_whole = false;
	m_subdivisions++;
}

namespace
{
// the speed of a body's fastest point: its centre's and its spin over half its box
btScalar fastestPointSpeed(const btRigidBody& body, const btVector3& aabbMin, const btVector3& aabbMax)
{
	return body.getLinearVelocity().length() + body.getAngularVelocity().length() * (aabbMax - aabbMin).length() / 2;
}
}  // namespace

bool JitStructure::threatens(const btRigidBody& other) const
{
	if (!m_whole) return false;
	if (other.isKinematicObject()) return other.getLinearVelocity().length2() + other.getAngularVelocity().length2() > 0;
	if (!(other.getInvMass() > 0)) return false;
	// its closing speed: the velocity of its centre towards the nearest point of the structure's box (all of it from
	// inside the box), and its spin over half its own box
	btVector3 minimum, maximum, otherMin, otherMax;
	m_wholeBody->getAabb(minimum, maximum);
	other.getAabb(otherMin, otherMax);
	const btVector3 centre = other.getCenterOfMassPosition();
	btVector3 nearest = centre;
	nearest.setMax(minimum);
	nearest.setMin(maximum);
	const btVector3 towards = nearest - centre;
	const btVector3 v = other.getLinearVelocity();
	const btScalar closing = towards.length2() > 0 ? btMax(btScalar(0), v.dot(towards) / towards.length()) : v.length();
	const double speed = double(closing + other.getAngularVelocity().length() * (otherMax - otherMin).length() / 2);
	return 0.5 * speed * speed / double(other.getInvMass()) > m_yieldEnergy_j;
}

bool JitStructure::subdivideIfThreatened(double lookahead_s)
{
	if (!m_whole) return false;
	btVector3 minimum, maximum;
	m_wholeBody->getAabb(minimum, maximum);
	bool threatened = false;
	const btCollisionObjectArray& objects = m_world.getCollisionObjectArray();
	for (int i = 0; i < objects.size() && !threatened; i++)
	{
		const btRigidBody* other = btRigidBody::upcast(objects[i]);
		if (!other || other == m_wholeBody.get() || !threatens(*other)) continue;
		btVector3 otherMin, otherMax;
		other->getAabb(otherMin, otherMax);
		const btScalar r = fastestPointSpeed(*other, otherMin, otherMax) * btScalar(lookahead_s);
		threatened = TestAabbAgainstAabb2(minimum - btVector3(r, r, r), maximum + btVector3(r, r, r), otherMin, otherMax);
	}
	if (threatened) subdivide();
	return threatened;
}

bool JitStructure::mergeIfAtRest()
{
	if (m_whole || !std::all_of(m_bodies.begin(), m_bodies.end(), [](const btRigidBody* b)
								{ return b->getActivationState() == ISLAND_SLEEPING; }))
		return false;
	merge();
	return true;
}

namespace
{
// the whole structures a swept box overlaps in the broadphase
struct Reached : btBroadphaseAabbCallback
{
	const std::unordered_map<const void*, JitStructure*>& wholeBodies;
	std::vector<JitStructure*> found;
	explicit Reached(const std::unordered_map<const void*, JitStructure*>& w) : wholeBodies(w) {}
	bool process(const btBroadphaseProxy* proxy) override
	{
		const auto it = wholeBodies.find(proxy->m_clientObject);
		if (it != wholeBodies.end() && std::find(found.begin(), found.end(), it->second) == found.end()) found.push_back(it->second);
		return true;
	}
};
}  // namespace

int JitStructureSet::subdivideThreatened(double lookahead_s)
{
	int count = 0;
	// the whole structures' bodies, made again only when a structure has merged or subdivided since
	long transitions = 0;
	for (const JitStructure* s : m_structures) transitions += s->subdivisions() + s->merges();
	if (transitions != m_transitions)
	{
		m_wholeBodies.clear();
		for (JitStructure* s : m_structures)
			if (s->whole()) m_wholeBodies[s->wholeBody()] = s;
		m_transitions = transitions;
	}
	std::vector<JitStructure*> threatened;
	const btCollisionObjectArray& objects = m_world.getCollisionObjectArray();
	for (int i = 0; i < objects.size(); i++)
	{
		const btRigidBody* mover = btRigidBody::upcast(objects[i]);
		if (!mover || !(mover->isKinematicObject() || (mover->getInvMass() > 0 && mover->isActive()))) continue;
		btVector3 minimum, maximum;
		mover->getAabb(minimum, maximum);
		const btScalar speed = fastestPointSpeed(*mover, minimum, maximum);
		// too slow to yield any of them, however it comes at them (most moving bodies: debris, segments at rest)
		if (!mover->isKinematicObject() && 0.5 * double(speed * speed) / double(mover->getInvMass()) <= m_leastYield_j) continue;
		const btScalar r = speed * btScalar(lookahead_s);
		if (!(r > 0)) continue;
		if (m_wholeBodies.empty()) break;
		Reached reached(m_wholeBodies);
		m_world.getBroadphase()->aabbTest(minimum - btVector3(r, r, r), maximum + btVector3(r, r, r), reached);
		for (JitStructure* s : reached.found)
			if (s->threatens(*mover) && std::find(threatened.begin(), threatened.end(), s) == threatened.end()) threatened.push_back(s);
	}
	// after the loop: a subdivision changes the world's array of objects
	for (JitStructure* s : threatened)
	{
		m_wholeBodies.erase(s->wholeBody());
		s->subdivide();
		count++;
		m_transitions++;
	}
	return count;
}

int JitStructureSet::mergeAtRest()
{
	int count = 0;
	for (JitStructure* s : m_structures) count += s->mergeIfAtRest() ? 1 : 0;
	return count;
}
}  // namespace plastic
