// A zero-gravity world with a static support at the origin's left (a 0.2 m cube centred at x = -0.1 m) for the
// toolkit's cantilever tests; the constraint solver is Bullet's sequential impulse or btDirectJointSolver.
#pragma once

#include <memory>

#include "btBulletDynamicsCommon.h"

struct CantileverRig
{
	btDefaultCollisionConfiguration configuration;
	btCollisionDispatcher dispatcher{&configuration};
	btDbvtBroadphase broadphase;
	std::unique_ptr<btConstraintSolver> solver;
	std::unique_ptr<btDiscreteDynamicsWorld> worldPtr;
	btDiscreteDynamicsWorld& world;
	btBoxShape supportShape{btVector3(0.1, 0.1, 0.1)};
	btRigidBody support{btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &supportShape)};

	CantileverRig(int iterations, bool directSolver)
		: solver(directSolver ? static_cast<btConstraintSolver*>(new btDirectJointSolver()) : new btSequentialImpulseConstraintSolver()),
		  worldPtr(std::make_unique<btDiscreteDynamicsWorld>(&dispatcher, &broadphase, solver.get(), &configuration)),
		  world(*worldPtr)
	{
		world.setGravity(btVector3(0, 0, 0));
		world.getSolverInfo().m_numIterations = iterations;
		support.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(-0.1, 0, 0)));
		world.addRigidBody(&support, 0, 0);
	}
	~CantileverRig() { world.removeRigidBody(&support); }
};
