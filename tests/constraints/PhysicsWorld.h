// A minimal dynamics world for constraint tests: no gravity, no deactivation, owns its bodies.
#pragma once

#include <memory>
#include <vector>

#include "btBulletDynamicsCommon.h"

class PhysicsWorld
{
public:
	PhysicsWorld()
		: dispatcher(&configuration), world(&dispatcher, &broadphase, &solver, &configuration)
	{
		world.setGravity(btVector3(0, 0, 0));
	}
	~PhysicsWorld()
	{
		for (int i = world.getNumConstraints() - 1; i >= 0; i--) world.removeConstraint(world.getConstraint(i));
		for (auto& body : bodies) world.removeRigidBody(body.get());
	}

	// A box of half extents h (m) and mass (kg) at position, no collisions with anything.
	btRigidBody* addBox(const btVector3& h, double mass, const btVector3& position)
	{
		shapes.push_back(std::make_unique<btBoxShape>(h));
		btVector3 inertia(0, 0, 0);
		if (mass > 0) shapes.back()->calculateLocalInertia(btScalar(mass), inertia);
		btTransform t;
		t.setIdentity();
		t.setOrigin(position);
		btRigidBody::btRigidBodyConstructionInfo info(btScalar(mass), nullptr, shapes.back().get(), inertia);
		info.m_startWorldTransform = t;
		bodies.push_back(std::make_unique<btRigidBody>(info));
		bodies.back()->setActivationState(DISABLE_DEACTIVATION);
		world.addRigidBody(bodies.back().get(), 0, 0);
		return bodies.back().get();
	}

	double kineticEnergy(const btRigidBody* body) const
	{
		if (body->getInvMass() == 0) return 0;
		btVector3 localW = body->getWorldTransform().getBasis().transpose() * body->getAngularVelocity();
		btVector3 I = body->getLocalInertia();
		return 0.5 / body->getInvMass() * body->getLinearVelocity().length2() +
			   0.5 * (I.x() * localW.x() * localW.x() + I.y() * localW.y() * localW.y() + I.z() * localW.z() * localW.z());
	}

	btDefaultCollisionConfiguration configuration;
	btCollisionDispatcher dispatcher;
	btDbvtBroadphase broadphase;
	btSequentialImpulseConstraintSolver solver;
	btDiscreteDynamicsWorld world;
	std::vector<std::unique_ptr<btBoxShape>> shapes;
	std::vector<std::unique_ptr<btRigidBody>> bodies;
};
