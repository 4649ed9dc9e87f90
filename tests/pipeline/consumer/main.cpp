// Steps a world with a plastic hinge through the installed, patched Bullet.
#include <btBulletDynamicsCommon.h>
#include <cstdio>

int main()
{
	btDefaultCollisionConfiguration configuration;
	btCollisionDispatcher dispatcher(&configuration);
	btDbvtBroadphase broadphase;
	btSequentialImpulseConstraintSolver solver;
	btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
	btBoxShape box(btVector3(0.5, 0.05, 0.05));
	btVector3 inertia;
	box.calculateLocalInertia(1, inertia);
	btRigidBody body(1, nullptr, &box, inertia);
	world.addRigidBody(&body);
	btPlasticHingeConstraint hinge(body, btVector3(0, 0, 0), btVector3(0, 1, 0));
	hinge.setPlasticMoment(1);
	world.addConstraint(&hinge);
	body.applyTorque(btVector3(0, 5, 0));
	world.stepSimulation(btScalar(0.01), 0);
	world.stepSimulation(btScalar(0.01), 0);
	world.removeConstraint(&hinge);
	world.removeRigidBody(&body);
	std::printf("plastic rotation %g rad\n", double(hinge.getCurrentPlasticRotation()));
	return hinge.getCurrentPlasticRotation() > 0 ? 0 : 1;
}
