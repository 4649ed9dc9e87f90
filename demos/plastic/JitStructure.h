// A structure anchored to static bodies (a building on the ground) that costs static bodies while it is at rest and
// nothing threatens it, and is jointed again, member by member, just before an impact or a neighbour's load that can
// yield one of its joints (thesis 4.2, just-in-time subdivision, for frames: members joined at nodes, fixed to the ground).
//
// A whole member's bodies (its segments) are static and out of the world with every joint that touches no subdivided
// member, and one static body of the whole members' shapes where they are (a compound) stands in the world for contacts:
// the solver sees nothing of them, and a member that has come to rest is where it stopped, so nothing moves that should.
// A subdivided member's bodies have their masses back, at rest, with its joints; a joint between a subdivided member and
// a whole one holds to the whole one as to a fixed body. The joints are the same objects throughout and keep their
// plastic state (set, accumulated rotation, absorbed energy, fatigue damage). A member merges only when Bullet has put
// every one of its bodies to sleep (so a member whose bodies may not sleep stays jointed once it has been hit), and the
// kinetic energy its bodies had then, none once asleep, is booked as lost (mergeLoss_j); it is never gained.
//
// A blow loads the members joined to the one it hits in the step it lands, and those joined to them: those whose capacity
// the blow's momentum over a step can reach subdivide with it (in a rigid-plastic frame, whose joints carry any force, the
// whole frame). A load that grows over steps reaches the members one after the other: a subdivided member loads its whole
// neighbours through the joints between them, each such joint reports the force and moment it puts on the whole member
// (btJointFeedback), and a whole member subdivides before the step in which they can reach the least capacity of its
// joints. The moment anywhere in the member is at most the joints' moments plus their
// forces times the member's extent plus its own weight times its extent; the next step's is taken as this step's plus
// its last increase.
//
// Where JitMember (one free or supported member) moves as one body while whole, a JitStructure does not move at all: it
// is for what stands on the ground until something hits it.
#pragma once

#include <algorithm>
#include <limits>
#include <memory>
#include <unordered_map>
#include <vector>

#include "JointFactory.h"
#include "btBulletDynamicsCommon.h"

namespace plastic
{
// One joint of a JitStructure and what yields it: the least energy (jointYieldEnergy_j), the least moment (its bending
// and torsion capacities, N m) and the least force (its axial and shear capacities, N).
struct JitJoint
{
	btTypedConstraint* constraint = nullptr;
	double yieldEnergy_j = 0;
	double yieldMoment_nm = std::numeric_limits<double>::infinity();
	double yieldForce_n = std::numeric_limits<double>::infinity();
};
// a joint made by makeJoint from spec, with the capacities of the spec
JitJoint jitJoint(const Joint& joint, const JointSpec& spec);

class JitStructure
{
public:
	// members: the bodies of each member, in the world (a body in no member is a support, static); joints: every joint
	// between them and to the static bodies they stand on, in the world. A member's capacities are the least of the joints
	// that touch it; a joint between no member's bodies is left as it is. The caller keeps owning them; the structure starts jointed (subdivided) and puts them back so when it
	// is destroyed.
	JitStructure(btDiscreteDynamicsWorld& world, std::vector<std::vector<btRigidBody*>> members, const std::vector<JitJoint>& joints);
	// One member of them all, every joint yielding at yieldEnergy_j (the least energy that yields one of them), no
	// neighbours: the whole structure subdivides and merges at once.
	JitStructure(btDiscreteDynamicsWorld& world, std::vector<btRigidBody*> bodies, std::vector<btTypedConstraint*> joints, double yieldEnergy_j);
	~JitStructure();
	JitStructure(const JitStructure&) = delete;
	JitStructure& operator=(const JitStructure&) = delete;

	// every member whole
	bool whole() const { return m_wholeMembers == int(m_members.size()); }
	int members() const { return int(m_members.size()); }
	bool memberWhole(int member) const { return m_members[size_t(member)].whole; }
	const std::vector<btRigidBody*>& memberBodies(int member) const { return m_members[size_t(member)].bodies; }
	// the static body that stands in the world for the whole members, nullptr when none is
	const btRigidBody* wholeBody() const { return m_wholeBody.get(); }
	// every member's, member by member
	const std::vector<btRigidBody*>& bodies() const { return m_bodies; }

	// Makes every member whole now, wherever and however fast its bodies are (their kinetic energy is booked as lost).
	void merge();
	// Makes every member jointed again: their bodies at rest where they are, their joints in the world.
	void subdivide();
	void subdivideMember(int member);
	// Before a step: subdivides each whole member that a body whose swept box reaches it within lookahead_s can bring more
	// than its yield energy to (threatens), or that its subdivided neighbours can yield in the step. Returns how many
	// members subdivided. It looks at every body of the world; many structures in one world use a JitStructureSet, which
	// looks only at the bodies that move.
	int subdivideIfThreatened(double lookahead_s);
	// Marks the whole members that mover, its box swept by its fastest point's speed over lookahead_s, reaches and
	// threatens (it can bring more than a member's yield energy to it: 1/2 m v^2 with v its closing speed, its centre's
	// velocity towards the nearest point of the member's box, all of it from inside the box, and its spin over half its own
	// box; a moving kinematic body always can, a body that does not collide with the structure by the collision filter
	// cannot), and, through their joints and on through those of the members it marks, the whole members whose least
	// capacity the force of its whole momentum over lookahead_s can reach (over a member's extent, for a moment); the next
	// subdivideMarked subdivides them. Returns how many it marked.
	int markThreatened(const btRigidBody& mover, double lookahead_s);
	// Subdivides the marked members and the whole members its subdivided ones can yield in the step (above). Returns how
	// many subdivided.
	int subdivideMarked();
	// After a step: merges each subdivided member whose bodies are all asleep. Returns how many merged.
	int mergeIfAtRest();

	double mergeLoss_j() const { return m_mergeLoss_j; }
	// the least energy that yields one of its joints
	double yieldEnergy_j() const { return m_yieldEnergy_j; }
	// members subdivided and merged so far, one by one
	int subdivisions() const { return m_subdivisions; }
	int merges() const { return m_merges; }

private:
	struct Saved
	{
		btScalar mass = 0;
		btVector3 inertia{0, 0, 0};
		int group = 0, mask = 0;  // its collision filter in the world
	};
	struct Member
	{
		std::vector<btRigidBody*> bodies;
		std::vector<Saved> saved;
		std::vector<int> nodeJoints;  // indices of the joints between it and another member
		double yieldEnergy_j = std::numeric_limits<double>::infinity();
		double yieldMoment_nm = std::numeric_limits<double>::infinity();
		double yieldForce_n = std::numeric_limits<double>::infinity();
		double mass_kg = 0;
		btVector3 boxMin{0, 0, 0}, boxMax{0, 0, 0};  // while whole
		double extent_m = 0;                         // while whole: its box's diagonal
		double lastMoment_nm = 0, lastForce_n = 0;   // the neighbours' bounds at the last check
		bool loadChecked = false;                    // since it was last made whole
		bool whole = false;
		bool marked = false;
	};
	struct JointSlot
	{
		JitJoint joint;
		int memberA = -1, memberB = -1;  // -1: a support
		bool disableCollisions = false;  // as it was added to the world
		bool inWorld = true;
		bool ownFeedback = false;
	};
	void init(std::vector<std::vector<btRigidBody*>> members, const std::vector<JitJoint>& joints);
	// makes member i whole where toWhole[i], subdivided elsewhere
	void transition(const std::vector<bool>& toWhole);
	bool threatensMember(const Member& member, const btRigidBody& other) const;
	int memberIndex(const Member& member) const { return int(&member - m_members.data()); }
	// marks a member for the next subdivideMarked; false if it was marked already
	bool mark(Member& member);
	bool collides(const btRigidBody& other) const;
	// marks the whole members its subdivided neighbours can yield in the next step
	void markLoaded();

	btDiscreteDynamicsWorld& m_world;
	std::vector<Member> m_members;
	std::vector<JointSlot> m_joints;
	std::vector<btJointFeedback> m_feedback;  // one per joint (used by the node joints without one of their own)
	std::vector<btRigidBody*> m_bodies;
	double m_yieldEnergy_j = std::numeric_limits<double>::infinity();
	std::unique_ptr<btCompoundShape> m_wholeShape;
	std::unique_ptr<btRigidBody> m_wholeBody;
	int m_wholeMembers = 0;
	int m_marked = 0;
	double m_mergeLoss_j = 0;
	int m_subdivisions = 0;
	int m_merges = 0;
};

// Many structures in one world (a city): before each step only the bodies that move are tested against the broadphase,
// each one's box swept over the lookahead, so that a step costs what the moving bodies cost and not what the standing
// structures do (but for a scan of the world's objects to find the moving ones).
class JitStructureSet
{
public:
	explicit JitStructureSet(btDiscreteDynamicsWorld& world) : m_world(world) {}
	void add(JitStructure& structure)
	{
		m_structures.push_back(&structure);
		m_leastYield_j = std::min(m_leastYield_j, structure.yieldEnergy_j());
	}
	const std::vector<JitStructure*>& structures() const { return m_structures; }
	// Before a step: every awake dynamic (or moving kinematic) body's box, swept by its fastest point's speed over
	// lookahead_s, against the whole structures' bodies in the broadphase; each member it reaches and threatens subdivides,
	// and each whole member that its subdivided neighbours can yield. Returns how many members did.
	int subdivideThreatened(double lookahead_s);
	// After a step: merges every subdivided member whose bodies are all asleep. Returns how many did.
	int mergeAtRest();

private:
	btDiscreteDynamicsWorld& m_world;
	std::vector<JitStructure*> m_structures;
	double m_leastYield_j = std::numeric_limits<double>::infinity();  // of them all: a body with less energy threatens none
	std::unordered_map<const void*, JitStructure*> m_wholeBodies;     // the static bodies of their whole members
	long m_transitions = -1;                                          // their merges and subdivisions when it was made
};
}  // namespace plastic
