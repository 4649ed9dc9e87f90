// A world with Bullet's default collision setup and either btDirectJointSolver (patch 0019) or upstream's sequential
// impulse, for tests that check the patches against upstream's solver directly rather than through the toolkit.
#pragma once

#include <memory>

#include "btBulletDynamicsCommon.h"

struct SolverWorld
{
	btDefaultCollisionConfiguration configuration;
	btCollisionDispatcher dispatcher{&configuration};
	btDbvtBroadphase broadphase;
	std::unique_ptr<btConstraintSolver> solver;
	std::unique_ptr<btDiscreteDynamicsWorld> worldPtr;
	btDiscreteDynamicsWorld& world;
	const bool direct;

	explicit SolverWorld(bool directSolver)
		: solver(directSolver ? static_cast<btConstraintSolver*>(new btDirectJointSolver()) : new btSequentialImpulseConstraintSolver()),
		  worldPtr(std::make_unique<btDiscreteDynamicsWorld>(&dispatcher, &broadphase, solver.get(), &configuration)),
		  world(*worldPtr),
		  direct(directSolver)
	{
	}

	// the calls the direct solver handed to sequential impulse (0 with sequential impulse itself)
	int fallbacks() const { return direct ? static_cast<const btDirectJointSolver*>(solver.get())->getNumFallbacks() : 0; }
	// the calls the direct solver solved again without the contacts' position correction (patch 0038)
	int relaxedCalls() const { return direct ? static_cast<const btDirectJointSolver*>(solver.get())->getNumRelaxedCalls() : 0; }
};
