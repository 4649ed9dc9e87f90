// The constraints every island gets from btDiscreteDynamicsWorld, with island splitting on (the default): a solver
// that records each solveGroup call prints the island's bodies and constraint ids in order. The test builds it
// against the patched and an unpatched BulletDynamics and requires identical output, so the binary search of the
// island lookup patch hands every island the same constraints as the linear scan did.
// The scene: 400 chains of 1 to 5 boxes, some hung from static anchors, some joined in pairs, some left to fall
// asleep, joints that break on the way (new islands), boxes that land on each other (contact islands).
#include <cstdio>
#include <memory>
#include <vector>

#include "btBulletDynamicsCommon.h"

namespace
{
class RecordingSolver : public btSequentialImpulseConstraintSolver
{
public:
	int m_calls = 0;
	btScalar solveGroup(btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds, int numManifolds,
						btTypedConstraint** constraints, int numConstraints, const btContactSolverInfo& info, btIDebugDraw* debugDrawer,
						btDispatcher* dispatcher) override
	{
		std::printf("group %d: %d bodies, %d manifolds, constraints", m_calls++, numBodies, numManifolds);
		for (int i = 0; i < numConstraints; i++) std::printf(" %d", constraints[i]->getUserConstraintId());
		std::printf("\n");
		return btSequentialImpulseConstraintSolver::solveGroup(bodies, numBodies, manifolds, numManifolds, constraints, numConstraints, info,
															   debugDrawer, dispatcher);
	}
};

struct Scene
{
	btDefaultCollisionConfiguration configuration;
	btCollisionDispatcher dispatcher{&configuration};
	btDbvtBroadphase broadphase;
	RecordingSolver solver;
	btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
	btBoxShape shape{btVector3(0.2, 0.2, 0.2)};
	btBoxShape groundShape{btVector3(40, 1, 20)};
	std::vector<std::unique_ptr<btRigidBody>> bodies;
	std::vector<std::unique_ptr<btTypedConstraint>> joints;

	btRigidBody* box(btScalar mass, const btVector3& position)
	{
		btVector3 inertia(0, 0, 0);
		if (mass > 0) shape.calculateLocalInertia(mass, inertia);
		btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, &shape, inertia);
		info.m_startWorldTransform.setIdentity();
		info.m_startWorldTransform.setOrigin(position);
		bodies.push_back(std::make_unique<btRigidBody>(info));
		world.addRigidBody(bodies.back().get());
		return bodies.back().get();
	}
	void join(btRigidBody* a, btRigidBody* b, const btVector3& pivot)
	{
		btTransform p(btQuaternion::getIdentity(), pivot);
		auto* h = new btHingeConstraint(*a, *b, a->getWorldTransform().inverse() * p, b->getWorldTransform().inverse() * p);
		h->setUserConstraintId(static_cast<int>(joints.size()));
		joints.emplace_back(h);
		// some joints break on the way
		if (joints.size() % 7 == 3) h->setBreakingImpulseThreshold(btScalar(0.5 + 0.01 * (joints.size() % 50)));
		world.addConstraint(h, true);
	}

	Scene()
	{
		unsigned seed = 12345;
		auto next = [&seed]() { return (seed = seed * 1103515245u + 12345u) >> 16; };
		btRigidBody* previousChainEnd = nullptr;
		for (int c = 0; c < 400; c++)
		{
			const btScalar x = btScalar(3.0 * (c % 20)), z = btScalar(1.0 * (c / 20));
			const int length = 1 + static_cast<int>(next() % 5);
			btRigidBody* previous = nullptr;
			if (next() % 3 == 0) previous = box(0, btVector3(x, 10, z));  // a static anchor
			for (int k = 0; k < length; k++)
			{
				btRigidBody* b = box(1, btVector3(x + btScalar(0.45 * k), btScalar(10 - 0.05 * k), z));
				if (c % 5 == 0) b->setActivationState(DISABLE_DEACTIVATION);
				if (previous) join(previous, b, btVector3(x + btScalar(0.45 * k) - btScalar(0.225), btScalar(10 - 0.05 * k), z));
				previous = b;
			}
			// every eleventh chain is tied to the one before it
			if (previousChainEnd && c % 11 == 0) join(previousChainEnd, previous, previous->getCenterOfMassPosition());
			previousChainEnd = previous;
		}
		// the ground: the chains land, pile up (contact islands) and some fall asleep
		btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, &groundShape);
		info.m_startWorldTransform.setIdentity();
		info.m_startWorldTransform.setOrigin(btVector3(30, 7, 10));
		bodies.push_back(std::make_unique<btRigidBody>(info));
		world.addRigidBody(bodies.back().get());
	}
	~Scene()
	{
		// the world is destroyed after the members declared below it: leave it empty first
		for (auto& j : joints) world.removeConstraint(j.get());
		for (auto& b : bodies) world.removeRigidBody(b.get());
	}
};
}  // namespace

int main()
{
	Scene scene;
	for (int step = 0; step < 300; step++)
	{
		// one island per solveGroup call first, then upstream's default batching of small islands (128)
		scene.world.getSolverInfo().m_minimumSolverBatchSize = step < 150 ? 1 : 128;
		std::printf("step %d\n", step);
		scene.world.stepSimulation(btScalar(1.0 / 60.0), 0);
	}
	return 0;
}
