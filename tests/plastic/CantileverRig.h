// A zero-gravity world with a static support at the origin's left (a 0.2 m cube centred at x = -0.1 m) for the
// toolkit's cantilever tests; the constraint solver is Bullet's sequential impulse or btDirectJointSolver.
#pragma once

#include <memory>

#include "btBulletDynamicsCommon.h"
#include "plastic/BeamBuilder.h"
#include "../common/SolverWorld.h"

struct CantileverRig : SolverWorld
{
	btBoxShape supportShape{btVector3(0.1, 0.1, 0.1)};
	btRigidBody support{btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &supportShape)};

	CantileverRig(int iterations, bool directSolver) : SolverWorld(directSolver)
	{
		world.setGravity(btVector3(0, 0, 0));
		world.getSolverInfo().m_numIterations = iterations;
		support.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(-0.1, 0, 0)));
		world.addRigidBody(&support, 0, 0);
	}
	~CantileverRig() { world.removeRigidBody(&support); }
};

// The tests' member: 2 m of steel in 4 segments along x from the support, its main bending axis z
inline plastic::BeamSpec cantileverSpec(const plastic::SectionProperties& section, plastic::JointMethod method)
{
	plastic::BeamSpec spec;
	spec.start_m = btVector3(0, 0, 0);
	spec.end_m = btVector3(2, 0, 0);
	spec.segments = 4;
	spec.joint.section = section;
	spec.joint.material = plastic::steel();
	spec.bending_axis = btVector3(0, 0, 1);
	spec.joint.method = method;
	return spec;
}
