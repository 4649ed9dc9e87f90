#include "JitStructure.h"

#include "EnergyLedger.h"

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

// the speed of a body's fastest point: its centre's and its spin over half its box
btScalar fastestPointSpeed(const btRigidBody& body, const btVector3& aabbMin, const btVector3& aabbMax)
{
	return body.getLinearVelocity().length() + body.getAngularVelocity().length() * (aabbMax - aabbMin).length() / 2;
}
}  // namespace

JitJoint jitJoint(const Joint& joint, const JointSpec& spec)
{
	const SectionCapacities cap = jointCapacities(spec);
	JitJoint j;
	j.constraint = joint.constraint.get();
	j.yieldEnergy_j = jointYieldEnergy_j(spec);
	j.yieldMoment_nm = std::min({cap.plastic_moment_y_nm, cap.plastic_moment_z_nm, cap.torque_nm});
	j.yieldForce_n = std::min(cap.axial_n, cap.shear_n);
	return j;
}

JitStructure::JitStructure(btDiscreteDynamicsWorld& world, std::vector<std::vector<btRigidBody*>> members, const std::vector<JitJoint>& joints)
	: m_world(world)
{
	init(std::move(members), joints);
}

JitStructure::JitStructure(btDiscreteDynamicsWorld& world, std::vector<btRigidBody*> bodies, std::vector<btTypedConstraint*> joints, double yieldEnergy_j)
	: m_world(world)
{
	std::vector<JitJoint> all;
	for (btTypedConstraint* c : joints)
	{
		JitJoint j;
		j.constraint = c;
		j.yieldEnergy_j = yieldEnergy_j;
		all.push_back(j);
	}
	init({std::move(bodies)}, all);
}

void JitStructure::init(std::vector<std::vector<btRigidBody*>> members, const std::vector<JitJoint>& joints)
{
	std::unordered_map<const btRigidBody*, int> memberOf;
	for (auto& bodies : members)
	{
		Member m;
		m.bodies = std::move(bodies);
		for (btRigidBody* b : m.bodies)
		{
			memberOf[b] = int(m_members.size());
			m_bodies.push_back(b);
			Saved s;
			s.mass = b->getInvMass() > 0 ? btScalar(1) / b->getInvMass() : btScalar(0);
			const btVector3& inv = b->getInvInertiaDiagLocal();
			s.inertia = btVector3(inv.x() > 0 ? 1 / inv.x() : 0, inv.y() > 0 ? 1 / inv.y() : 0, inv.z() > 0 ? 1 / inv.z() : 0);
			const btBroadphaseProxy* proxy = b->getBroadphaseHandle();
			s.group = proxy ? proxy->m_collisionFilterGroup : int(btBroadphaseProxy::DefaultFilter);
			s.mask = proxy ? proxy->m_collisionFilterMask : int(btBroadphaseProxy::AllFilter);
			m.saved.push_back(s);
			m.mass_kg += double(s.mass);
		}
		m_members.push_back(std::move(m));
	}
	m_feedback.resize(joints.size());
	for (const JitJoint& j : joints)
	{
		JointSlot slot;
		slot.joint = j;
		slot.disableCollisions = hasConstraintRef(j.constraint->getRigidBodyA(), j.constraint);
		const auto a = memberOf.find(&j.constraint->getRigidBodyA()), b = memberOf.find(&j.constraint->getRigidBodyB());
		slot.memberA = a == memberOf.end() ? -1 : a->second;
		slot.memberB = b == memberOf.end() ? -1 : b->second;
		const int index = int(m_joints.size());
		for (int m : {slot.memberA, slot.memberB})
		{
			if (m < 0 || (m == slot.memberB && slot.memberA == slot.memberB)) continue;
			Member& member = m_members[size_t(m)];
			member.yieldEnergy_j = std::min(member.yieldEnergy_j, j.yieldEnergy_j);
			member.yieldMoment_nm = std::min(member.yieldMoment_nm, j.yieldMoment_nm);
			member.yieldForce_n = std::min(member.yieldForce_n, j.yieldForce_n);
		}
		if (slot.memberA >= 0 && slot.memberB >= 0 && slot.memberA != slot.memberB)
		{
			m_members[size_t(slot.memberA)].nodeJoints.push_back(index);
			m_members[size_t(slot.memberB)].nodeJoints.push_back(index);
			// the force and moment it puts on a whole member, when the other is subdivided
			if (!j.constraint->getJointFeedback())
			{
				j.constraint->setJointFeedback(&m_feedback[size_t(index)]);
				j.constraint->enableFeedback(true);
				slot.ownFeedback = true;
			}
		}
		m_yieldEnergy_j = std::min(m_yieldEnergy_j, j.yieldEnergy_j);
		m_joints.push_back(slot);
	}
}

JitStructure::~JitStructure()
{
	subdivide();
	for (JointSlot& slot : m_joints)
		if (slot.ownFeedback)
		{
			slot.joint.constraint->setJointFeedback(nullptr);
			slot.joint.constraint->enableFeedback(false);
		}
}

void JitStructure::transition(const std::vector<bool>& toWhole)
{
	bool changes = false;
	for (size_t i = 0; i < m_members.size(); i++) changes = changes || toWhole[i] != m_members[i].whole;
	if (!changes) return;
	if (m_wholeBody)
	{
		m_world.removeRigidBody(m_wholeBody.get());
		m_wholeBody.reset();
		m_wholeShape.reset();
	}
	// a joint of no member's bodies is left as it is
	auto belongs = [&toWhole](const JointSlot& s)
	{
		return (s.memberA < 0 && s.memberB < 0) || (s.memberA >= 0 && !toWhole[size_t(s.memberA)]) || (s.memberB >= 0 && !toWhole[size_t(s.memberB)]);
	};
	for (JointSlot& s : m_joints)
		if (s.inWorld && !belongs(s))
		{
			m_world.removeConstraint(s.joint.constraint);
			s.inWorld = false;
		}
	for (size_t i = 0; i < m_members.size(); i++)
	{
		Member& m = m_members[i];
		if (toWhole[i] == m.whole) continue;
		if (toWhole[i])
		{
			m.boxMin = btVector3(BT_LARGE_FLOAT, BT_LARGE_FLOAT, BT_LARGE_FLOAT);
			m.boxMax = -m.boxMin;
			for (size_t k = 0; k < m.bodies.size(); k++)
			{
				btRigidBody& b = *m.bodies[k];
				m_mergeLoss_j += kineticEnergy_j(b);
				btVector3 lo, hi;
				b.getAabb(lo, hi);
				m.boxMin.setMin(lo);
				m.boxMax.setMax(hi);
				m_world.removeRigidBody(&b);
				// static out of the world: a joint from a body that stays in the world holds to it as to a fixed body (as
				// btTypedConstraint::getFixedBody does), and the island manager must not take it for a body of an island
				b.setLinearVelocity(btVector3(0, 0, 0));
				b.setAngularVelocity(btVector3(0, 0, 0));
				b.setMassProps(0, btVector3(0, 0, 0));
				b.updateInertiaTensor();
				b.setIslandTag(-1);
				b.setCompanionId(-1);
			}
			m.extent_m = double((m.boxMax - m.boxMin).length());
			m.loadChecked = false;
			m.whole = true;
			m_wholeMembers++;
			m_merges++;
		}
		else
		{
			for (size_t k = 0; k < m.bodies.size(); k++)
			{
				btRigidBody& b = *m.bodies[k];
				b.setMassProps(m.saved[k].mass, m.saved[k].inertia);
				b.updateInertiaTensor();
				b.setLinearVelocity(btVector3(0, 0, 0));
				b.setAngularVelocity(btVector3(0, 0, 0));
				m_world.addRigidBody(&b, m.saved[k].group, m.saved[k].mask);
				b.activate(true);
			}
			m.whole = false;
			m_wholeMembers--;
			m_subdivisions++;
		}
	}
	for (Member& m : m_members) m.marked = false;
	m_marked = 0;
	for (JointSlot& s : m_joints)
		if (!s.inWorld && belongs(s))
		{
			// its loads of the last step it was solved in are not this step's
			if (btJointFeedback* fb = s.joint.constraint->getJointFeedback())
				for (btVector3* v : {&fb->m_appliedForceBodyA, &fb->m_appliedTorqueBodyA, &fb->m_appliedForceBodyB, &fb->m_appliedTorqueBodyB}) v->setZero();
			m_world.addConstraint(s.joint.constraint, s.disableCollisions);
			s.inWorld = true;
		}
	if (m_wholeMembers == 0) return;
	m_wholeShape = std::make_unique<btCompoundShape>(true, int(m_bodies.size()));
	const Member* first = nullptr;
	for (const Member& m : m_members)
	{
		if (!m.whole) continue;
		if (!first && !m.bodies.empty()) first = &m;
		for (const btRigidBody* b : m.bodies) m_wholeShape->addChildShape(b->getCenterOfMassTransform(), const_cast<btCollisionShape*>(b->getCollisionShape()));
	}
	btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, m_wholeShape.get());
	if (first)
	{
		info.m_friction = first->bodies.front()->getFriction();
		info.m_restitution = first->bodies.front()->getRestitution();
		info.m_rollingFriction = first->bodies.front()->getRollingFriction();
	}
	m_wholeBody = std::make_unique<btRigidBody>(info);
	// a subdivided body joined to a whole member's does not touch the whole body, as it does not touch that member's
	// bodies jointed (a joint's bodies do not collide): at a node the members' segments overlap
	for (const JointSlot& s : m_joints)
		if (s.inWorld && s.memberA >= 0 && s.memberB >= 0 && m_members[size_t(s.memberA)].whole != m_members[size_t(s.memberB)].whole)
			m_wholeBody->setIgnoreCollisionCheck(m_members[size_t(s.memberA)].whole ? &s.joint.constraint->getRigidBodyB() : &s.joint.constraint->getRigidBodyA(), true);
	// with its bodies' collision filter, so that it meets what they would
	if (!first)
		m_world.addRigidBody(m_wholeBody.get());
	else
		m_world.addRigidBody(m_wholeBody.get(), first->saved.front().group, first->saved.front().mask);
}

void JitStructure::merge() { transition(std::vector<bool>(m_members.size(), true)); }

void JitStructure::subdivide() { transition(std::vector<bool>(m_members.size(), false)); }

void JitStructure::subdivideMember(int member)
{
	std::vector<bool> toWhole;
	for (const Member& m : m_members) toWhole.push_back(m.whole);
	toWhole[size_t(member)] = false;
	transition(toWhole);
}

bool JitStructure::collides(const btRigidBody& other) const
{
	if (!m_wholeBody) return false;
	const btBroadphaseProxy* mine = m_wholeBody->getBroadphaseHandle();
	const btBroadphaseProxy* its = other.getBroadphaseHandle();
	if (!mine || !its) return true;
	return (mine->m_collisionFilterGroup & its->m_collisionFilterMask) && (its->m_collisionFilterGroup & mine->m_collisionFilterMask);
}

bool JitStructure::threatensMember(const Member& member, const btRigidBody& other) const
{
	if (!member.whole) return false;
	if (other.isKinematicObject()) return other.getLinearVelocity().length2() + other.getAngularVelocity().length2() > 0;
	if (!(other.getInvMass() > 0)) return false;
	// its closing speed: the velocity of its centre towards the nearest point of the member's box (all of it from inside
	// the box), and its spin over half its own box
	btVector3 otherMin, otherMax;
	other.getAabb(otherMin, otherMax);
	const btVector3 centre = other.getCenterOfMassPosition();
	btVector3 nearest = centre;
	nearest.setMax(member.boxMin);
	nearest.setMin(member.boxMax);
	const btVector3 towards = nearest - centre;
	const btVector3 v = other.getLinearVelocity();
	const btScalar closing = towards.length2() > 0 ? btMax(btScalar(0), v.dot(towards) / towards.length()) : v.length();
	const double speed = double(closing + other.getAngularVelocity().length() * (otherMax - otherMin).length() / 2);
	return 0.5 * speed * speed / double(other.getInvMass()) > member.yieldEnergy_j;
}

int JitStructure::markThreatened(const btRigidBody& mover, double lookahead_s)
{
	if (m_wholeMembers == 0 || &mover == m_wholeBody.get() || !collides(mover)) return 0;
	btVector3 moverMin, moverMax;
	mover.getAabb(moverMin, moverMax);
	const btScalar speed = fastestPointSpeed(mover, moverMin, moverMax);
	const btScalar reach = speed * btScalar(lookahead_s);
	const btVector3 r(reach, reach, reach);
	// the most force it can put on a member it hits within the lookahead: all its momentum in one step (a moving kinematic
	// body any force)
	const double force_n = mover.isKinematicObject() ? std::numeric_limits<double>::infinity() : double(speed) / double(mover.getInvMass()) / lookahead_s;
	int marked = 0;
	std::vector<Member*> reached;
	for (Member& m : m_members)
		if (threatensMember(m, mover) && TestAabbAgainstAabb2(m.boxMin - r, m.boxMax + r, moverMin, moverMax))
		{
			marked += mark(m);
			reached.push_back(&m);
		}
	// the whole members the blow loads through the joints of those it hits, in the step it lands (a joint's force is not
	// capped where a member's moment is: a blow on a column sways the frame): those whose capacity that force can reach
	// over their extent, and on through theirs
	while (!reached.empty())
	{
		const Member& m = *reached.back();
		reached.pop_back();
		for (int j : m.nodeJoints)
		{
			const JointSlot& s = m_joints[size_t(j)];
			Member& other = m_members[size_t(s.memberA == memberIndex(m) ? s.memberB : s.memberA)];
			if (!other.whole || other.marked || !(force_n * other.extent_m >= other.yieldMoment_nm || force_n >= other.yieldForce_n)) continue;
			marked += mark(other);
			reached.push_back(&other);
		}
	}
	return marked;
}

bool JitStructure::mark(Member& member)
{
	if (member.marked) return false;
	member.marked = true;
	m_marked++;
	return true;
}

void JitStructure::markLoaded()
{
	const double g = double(m_world.getGravity().length());
	for (Member& m : m_members)
	{
		if (!m.whole || m.marked) continue;
		// the forces and moments its subdivided neighbours put on it in the last step
		double moment = 0, force = 0;
		for (int j : m.nodeJoints)
		{
			const JointSlot& s = m_joints[size_t(j)];
			const bool onA = s.memberA == memberIndex(m);
			const int other = onA ? s.memberB : s.memberA;
			const btRigidBody& otherBody = onA ? s.joint.constraint->getRigidBodyB() : s.joint.constraint->getRigidBodyA();
			// an asleep neighbour's feedback is of the step it fell asleep in: it loads nothing now
			if (m_members[size_t(other)].whole || !s.joint.constraint->isEnabled() || !otherBody.isActive()) continue;
			const btJointFeedback* fb = s.joint.constraint->getJointFeedback();
			if (!fb) continue;
			const btVector3& F = onA ? fb->m_appliedForceBodyA : fb->m_appliedForceBodyB;
			const btVector3& T = onA ? fb->m_appliedTorqueBodyA : fb->m_appliedTorqueBodyB;
			moment += double(T.length()) + double(F.length()) * m.extent_m;
			force += double(F.length());
		}
		// (a member that merged at rest under its neighbours' loads holds them: no increase at its first check)
		const double nextMoment = moment + (m.loadChecked ? std::max(0.0, moment - m.lastMoment_nm) : 0.0) + m.mass_kg * g * m.extent_m;
		const double nextForce = force + (m.loadChecked ? std::max(0.0, force - m.lastForce_n) : 0.0) + m.mass_kg * g;
		m.loadChecked = true;
		m.lastMoment_nm = moment;
		m.lastForce_n = force;
		if (moment > 0 && (nextMoment >= m.yieldMoment_nm || nextForce >= m.yieldForce_n)) mark(m);
	}
}

int JitStructure::subdivideMarked()
{
	if (m_wholeMembers < int(m_members.size()) && m_wholeMembers > 0) markLoaded();
	if (m_marked == 0) return 0;
	std::vector<bool> toWhole;
	int count = 0;
	for (const Member& m : m_members)
	{
		toWhole.push_back(m.whole && !m.marked);
		count += m.whole && m.marked ? 1 : 0;
	}
	transition(toWhole);
	return count;
}

int JitStructure::subdivideIfThreatened(double lookahead_s)
{
	if (m_wholeMembers == 0) return 0;
	const btCollisionObjectArray& objects = m_world.getCollisionObjectArray();
	for (int i = 0; i < objects.size(); i++)
	{
		const btRigidBody* other = btRigidBody::upcast(objects[i]);
		if (!other || other == m_wholeBody.get()) continue;
		markThreatened(*other, lookahead_s);
	}
	return subdivideMarked();
}

int JitStructure::mergeIfAtRest()
{
	if (whole()) return 0;  // (most structures of a city, every step)
	std::vector<bool> toWhole;
	int count = 0;
	for (const Member& m : m_members)
	{
		const bool asleep = !m.whole && std::all_of(m.bodies.begin(), m.bodies.end(), [](const btRigidBody* b)
													{ return b->getActivationState() == ISLAND_SLEEPING; });
		toWhole.push_back(m.whole || asleep);
		count += asleep ? 1 : 0;
	}
	if (count > 0) transition(toWhole);
	return count;
}

namespace
{
// the structures whose whole members' body a swept box overlaps in the broadphase
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
	// the whole members' bodies, made again only when a member has merged or subdivided since
	long transitions = 0;
	for (const JitStructure* s : m_structures) transitions += s->subdivisions() + s->merges();
	if (transitions != m_transitions)
	{
		m_wholeBodies.clear();
		for (JitStructure* s : m_structures)
			if (s->wholeBody()) m_wholeBodies[s->wholeBody()] = s;
		m_transitions = transitions;
	}
	const btCollisionObjectArray& objects = m_world.getCollisionObjectArray();
	for (int i = 0; i < objects.size() && !m_wholeBodies.empty(); i++)
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
		Reached reached(m_wholeBodies);
		m_world.getBroadphase()->aabbTest(minimum - btVector3(r, r, r), maximum + btVector3(r, r, r), reached);
		for (JitStructure* s : reached.found) s->markThreatened(*mover, lookahead_s);
	}
	// after the loop: a subdivision changes the world's array of objects
	int count = 0;
	for (JitStructure* s : m_structures) count += s->subdivideMarked();
	return count;
}

int JitStructureSet::mergeAtRest()
{
	int count = 0;
	for (JitStructure* s : m_structures) count += s->mergeIfAtRest();
	return count;
}
}  // namespace plastic
