// An upstream-only scene: btHingeConstraint and btGeneric6DofSpring2Constraint used the way
// games use them today (range and locked limits, motors, servo, springs, both hinge
// code paths), with gravity and contacts. It prints every body's state after each second
// as exact hexadecimal floats. The test builds it twice, against the patched BulletDynamics
// and against an unpatched one, and requires identical output: the patches change nothing
// while their new settings stay at their defaults. With the argument `mlcp` the same scene
// runs under btMLCPSolver + btDantzigSolver (patch 0021 resizes its row offsets only).
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

#include "btBulletDynamicsCommon.h"
#include "BulletDynamics/MLCPSolvers/btDantzigSolver.h"
#include "BulletDynamics/MLCPSolvers/btMLCPSolver.h"

namespace
{
struct Scene
{
	btDefaultCollisionConfiguration configuration;
	btCollisionDispatcher dispatcher{&configuration};
	btDbvtBroadphase broadphase;
	btDantzigSolver dantzig;
	std::unique_ptr<btSequentialImpulseConstraintSolver> solver;
	btDiscreteDynamicsWorld world;
	std::vector<std::unique_ptr<btCollisionShape>> shapes;
	std::vector<std::unique_ptr<btRigidBody>> bodies;
	std::vector<std::unique_ptr<btTypedConstraint>> constraints;

	explicit Scene(bool mlcp)
		: solver(mlcp ? std::unique_ptr<btSequentialImpulseConstraintSolver>(new btMLCPSolver(&dantzig))
					  : std::make_unique<btSequentialImpulseConstraintSolver>()),
		  world(&dispatcher, &broadphase, solver.get(), &configuration)
	{
	}

	// A box of half extents h (m), mass (kg; 0 = static) at position (m).
	btRigidBody* box(const btVector3& h, btScalar mass, const btVector3& position)
	{
		return body(std::make_unique<btBoxShape>(h), mass, position);
	}
	btRigidBody* body(std::unique_ptr<btCollisionShape> shape, btScalar mass, const btVector3& position)
	{
		shapes.push_back(std::move(shape));
		btVector3 inertia(0, 0, 0);
		if (mass > 0) shapes.back()->calculateLocalInertia(mass, inertia);
		btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, shapes.back().get(), inertia);
		info.m_startWorldTransform.setIdentity();
		info.m_startWorldTransform.setOrigin(position);
		bodies.push_back(std::make_unique<btRigidBody>(info));
		bodies.back()->setActivationState(DISABLE_DEACTIVATION);
		world.addRigidBody(bodies.back().get());
		return bodies.back().get();
	}
	template <class T>
	T* add(std::unique_ptr<T> constraint)
	{
		T* raw = constraint.get();
		world.addConstraint(raw, true);
		constraints.push_back(std::move(constraint));
		return raw;
	}
	~Scene()
	{
		for (auto& c : constraints) world.removeConstraint(c.get());
		for (auto& b : bodies) world.removeRigidBody(b.get());
	}
};

btTransform frame(const btVector3& origin, const btQuaternion& rotation = btQuaternion::getIdentity())
{
	return btTransform(rotation, origin);
}
}  // namespace

int main(int argc, char** argv)
{
	Scene s(argc > 1 && std::strcmp(argv[1], "mlcp") == 0);
	s.world.setGravity(btVector3(0, -9.81, 0));
	s.box(btVector3(5, 0.5, 5), 0, btVector3(0, -0.5, 0));  // ground

	// Hinges: a ranged limit with a motor (frame-offset path), a locked limit (low == high,
	// the row patch 1 caps when asked), and the classic path without frame offset.
	btRigidBody* post = s.box(btVector3(0.05, 0.5, 0.05), 0, btVector3(-2, 1.5, 0));
	btRigidBody* door = s.box(btVector3(0.4, 0.5, 0.05), 3, btVector3(-1.5, 1.5, 0));
	auto* ranged = s.add(std::make_unique<btHingeConstraint>(*post, *door, btVector3(0.1, 0, 0), btVector3(-0.45, 0, 0), btVector3(0, 1, 0), btVector3(0, 1, 0)));
	ranged->setLimit(-0.8, 1.2, 0.9, 0.3, 1.0);
	ranged->enableAngularMotor(true, 2.0, 0.5);
	btRigidBody* arm = s.box(btVector3(0.3, 0.05, 0.05), 1, btVector3(-1.5, 3, 0));
	auto* locked = s.add(std::make_unique<btHingeConstraint>(*door, *arm, btVector3(0, 0.5, 0), btVector3(0, -0.1, 0), btVector3(0, 0, 1), btVector3(0, 0, 1)));
	locked->setLimit(0.3, 0.3);
	btRigidBody* pendulum = s.box(btVector3(0.05, 0.4, 0.05), 2, btVector3(1, 2.6, 0));
	auto* classic = s.add(std::make_unique<btHingeConstraint>(*pendulum, btVector3(0, 0.45, 0), btVector3(0, 0, 1), false));
	classic->setUseFrameOffset(false);
	classic->setLimit(-1.0, 1.0);
	pendulum->setAngularVelocity(btVector3(0, 0, 6));

	// Spring2: locked, ranged and free DOFs, a motor, a servo, springs with and without
	// damping, in a rotated frame.
	btRigidBody* base = s.box(btVector3(0.2, 0.2, 0.2), 0, btVector3(2, 2, 0));
	btRigidBody* cart = s.box(btVector3(0.2, 0.1, 0.1), 2, btVector3(2.6, 2, 0));
	btQuaternion tilt(btVector3(0, 0, 1), 0.4);
	auto* g6 = s.add(std::make_unique<btGeneric6DofSpring2Constraint>(*base, *cart, frame(btVector3(0.3, 0, 0), tilt), frame(btVector3(-0.3, 0, 0), tilt), RO_XYZ));
	g6->setLinearLowerLimit(btVector3(-0.2, 0, 1));
	g6->setLinearUpperLimit(btVector3(0.3, 0, -1));
	g6->setAngularLowerLimit(btVector3(-0.5, 0, 1));
	g6->setAngularUpperLimit(btVector3(0.5, 0, -1));
	g6->enableSpring(0, true);
	g6->setStiffness(0, 200);
	g6->setDamping(0, 0.5);
	g6->enableSpring(5, true);
	g6->setStiffness(5, 50);
	g6->enableMotor(3, true);
	g6->setTargetVelocity(3, 1.5);
	g6->setMaxMotorForce(3, 4);
	g6->enableMotor(2, true);
	g6->setServo(2, true);
	g6->setServoTarget(2, 0.1);
	g6->setTargetVelocity(2, 0.5);
	g6->setMaxMotorForce(2, 20);
	g6->setEquilibriumPoint();
	cart->setLinearVelocity(btVector3(1, 2, 0.5));

	// A second Spring2 stack that falls on the ground: contacts plus a stiff spring that
	// upstream softens (setStiffness limitIfNeeded).
	btRigidBody* lower = s.box(btVector3(0.2, 0.2, 0.2), 1, btVector3(0, 1, 1.5));
	btRigidBody* upper = s.box(btVector3(0.2, 0.2, 0.2), 1, btVector3(0, 1.6, 1.5));
	auto* stack = s.add(std::make_unique<btGeneric6DofSpring2Constraint>(*lower, *upper, frame(btVector3(0, 0.3, 0)), frame(btVector3(0, -0.3, 0))));
	stack->setLinearLowerLimit(btVector3(0, -0.1, 0));
	stack->setLinearUpperLimit(btVector3(0, 0.1, 0));
	stack->enableSpring(1, true);
	stack->setStiffness(1, 1e7);
	stack->setAngularLowerLimit(btVector3(0, 0, 0));
	stack->setAngularUpperLimit(btVector3(0, 0, 0));

	// Convex shapes that collide through GJK (btConvexConvexAlgorithm, btVoronoiSimplexSolver: patch 0018's global
	// stays at its default): a capsule, a cylinder and a convex hull tumbling onto the ground and each other.
	btRigidBody* capsule = s.body(std::make_unique<btCapsuleShape>(0.1, 0.4), 1, btVector3(0.5, 0.6, -1.5));
	capsule->setAngularVelocity(btVector3(1, 0.5, 2));
	btRigidBody* cylinder = s.body(std::make_unique<btCylinderShape>(btVector3(0.15, 0.2, 0.15)), 1, btVector3(0.6, 1.2, -1.4));
	cylinder->setAngularVelocity(btVector3(-2, 1, 0.3));
	const btScalar hullPoints[] = {0.2, 0, 0, -0.1, 0.17, 0, -0.1, -0.17, 0, 0, 0, 0.25, 0.05, 0.05, -0.15};
	s.body(std::make_unique<btConvexHullShape>(hullPoints, 5, int(3 * sizeof(btScalar))), 1, btVector3(0.4, 1.8, -1.6));

	const btScalar dt = 1.0 / 240;
	for (int second = 1; second <= 4; second++)
	{
		for (int i = 0; i < 240; i++) s.world.stepSimulation(dt, 0, dt);
		for (size_t b = 0; b < s.bodies.size(); b++)
		{
			const btTransform& t = s.bodies[b]->getWorldTransform();
			const btVector3& p = t.getOrigin();
			btQuaternion q = t.getRotation();
			const btVector3& v = s.bodies[b]->getLinearVelocity();
			const btVector3& w = s.bodies[b]->getAngularVelocity();
			std::printf("t=%d body=%zu p=%a %a %a q=%a %a %a %a v=%a %a %a w=%a %a %a\n", second, b,
						double(p.x()), double(p.y()), double(p.z()), double(q.x()), double(q.y()), double(q.z()), double(q.w()),
						double(v.x()), double(v.y()), double(v.z()), double(w.x()), double(w.y()), double(w.z()));
		}
	}
	return 0;
}
