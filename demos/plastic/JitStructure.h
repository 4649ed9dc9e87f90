// A structure anchored to static bodies (a building on the ground) that costs one static body while it is at rest and
// nothing threatens it, and is its jointed self again just before an impact that can yield one of its joints (thesis
// 4.2, just-in-time subdivision, for frames: members joined at nodes, fixed to the ground).
//
// Whole, its bodies (the members' segments) are static and out of the world with every one of its joints, and one static
// body of their shapes where they are (a compound) stands in the world for contacts: the solver sees nothing of it, and
// a structure that has come to rest is where it stopped, so nothing moves that should. Subdivided, its bodies get their
// masses back, at rest, with its joints; the joints are the same objects throughout and keep their plastic state (set,
// accumulated rotation, absorbed energy, fatigue damage). It merges only when Bullet has put every one of its bodies to
// sleep (so a structure whose bodies may not sleep stays jointed once it has been hit), and the kinetic energy its
// bodies had then, none once asleep, is booked as lost (mergeLoss_j); it is never gained.
//
// Where JitMember (one free or supported member) moves as one body while whole, a JitStructure does not move at all: it
// is for what stands on the ground until something hits it.
#pragma once

#include <algorithm>
#include <limits>
#include <memory>
#include <unordered_map>
#include <vector>

#include "btBulletDynamicsCommon.h"

namespace plastic
{
class JitStructure
{
public:
	// bodies: the structure's dynamic bodies, in the world; joints: every joint between them and to the static bodies they
	// stand on, in the world; yieldEnergy_j: the least energy that yields one of the joints (jointYieldEnergy_j of each
	// joint's spec). The caller keeps owning them; the structure starts jointed (subdivided) and puts them back so when it is
	// destroyed.
	JitStructure(btDiscreteDynamicsWorld& world, std::vector<btRigidBody*> bodies, std::vector<btTypedConstraint*> joints, double yieldEnergy_j);
	~JitStructure();
	JitStructure(const JitStructure&) = delete;
	JitStructure& operator=(const JitStructure&) = delete;

	bool whole() const { return m_whole; }
	// the static body that stands in the world for the structure while whole, nullptr when subdivided
	const btRigidBody* wholeBody() const { return m_whole ? m_wholeBody.get() : nullptr; }
	const std::vector<btRigidBody*>& bodies() const { return m_bodies; }

	// Makes it whole now, wherever and however fast its bodies are (their kinetic energy is booked as lost).
	void merge();
	// Makes it jointed again: its bodies at rest where they are, its joints in the world.
	void subdivide();
	// Before a step: subdivides the whole structure when a body whose swept box reaches it within lookahead_s can bring
	// more than yieldEnergy_j to it (threatens). Returns whether it subdivided. It looks at every body of the world; many
	// structures in one world use a JitStructureSet, which looks only at the bodies that move.
	bool subdivideIfThreatened(double lookahead_s);
	// Whether other, wherever it is, can bring more than yieldEnergy_j to the whole structure: 1/2 m v^2 with v its closing
	// speed (its centre's velocity towards the nearest point of the structure's box, all of it from inside the box) and
	// its spin over half its own box (the structure does not move while whole); a moving kinematic body always can.
	bool threatens(const btRigidBody& other) const;
	// After a step: merges the structure when every one of its bodies is asleep. Returns whether it merged.
	bool mergeIfAtRest();

	double mergeLoss_j() const { return m_mergeLoss_j; }
	double yieldEnergy_j() const { return m_yieldEnergy_j; }
	int subdivisions() const { return m_subdivisions; }
	int merges() const { return m_merges; }

private:
	struct Saved
	{
		btScalar mass = 0;
		btVector3 inertia{0, 0, 0};
		int group = 0, mask = 0;  // its collision filter in the world
	};
	btDiscreteDynamicsWorld& m_world;
	std::vector<btRigidBody*> m_bodies;
	std::vector<btTypedConstraint*> m_joints;
	std::vector<bool> m_jointsDisableCollisions;  // as they were added to the world
	std::vector<Saved> m_saved;
	double m_yieldEnergy_j;
	std::unique_ptr<btCompoundShape> m_wholeShape;
	std::unique_ptr<btRigidBody> m_wholeBody;
	bool m_whole = false;
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
	// lookahead_s, against the whole structures' bodies in the broadphase; each structure it reaches and threatens
	// subdivides. Returns how many did.
	int subdivideThreatened(double lookahead_s);
	// After a step: merges every subdivided structure whose bodies are all asleep. Returns how many did.
	int mergeAtRest();

private:
	btDiscreteDynamicsWorld& m_world;
	std::vector<JitStructure*> m_structures;
	double m_leastYield_j = std::numeric_limits<double>::infinity();  // of them all: a body with less energy threatens none
	std::unordered_map<const void*, JitStructure*> m_wholeBodies;     // the whole ones' bodies
	long m_transitions = -1;                                          // their merges and subdivisions when it was made
};
}  // namespace plastic
