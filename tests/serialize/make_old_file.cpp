// Writes tests/serialize/data/upstream-326.bullet with UNPATCHED Bullet (pybullet 3.2.7 src/, BT_BULLET_VERSION 326,
// single precision, 64-bit): the file an upstream user has today. Not part of the build; it was made once with
//   g++ -O1 -I<unpatched tree>/src make_old_file.cpp <unpatched tree>/src/btLinearMathAll.cpp \
//       <unpatched tree>/src/btBulletCollisionAll.cpp <unpatched tree>/src/btBulletDynamicsAll.cpp -o make_old_file
//   ./make_old_file upstream-326.bullet
// SerializeRoundTripTest.cpp (OldFileLoads) checks the values set here.
#include "btBulletDynamicsCommon.h"
#include "LinearMath/btSerializer.h"
#include <cstdio>

int main(int argc, char** argv)
{
	if (argc != 2)
	{
		std::fprintf(stderr, "usage: %s out.bullet\n", argv[0]);
		return 2;
	}
	btDefaultCollisionConfiguration config;
	btCollisionDispatcher dispatcher(&config);
	btDbvtBroadphase broadphase;
	btSequentialImpulseConstraintSolver solver;
	btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
	world.setGravity(btVector3(0, -9.81f, 0));

	btBoxShape box(btVector3(0.5f, 0.1f, 0.1f));
	btBoxShape ground(btVector3(10, 0.5f, 10));
	btAlignedObjectArray<btRigidBody*> bodies;
	btTransform t;
	t.setIdentity();
	t.setOrigin(btVector3(0, -3, 0));
	bodies.push_back(new btRigidBody(0, 0, &ground));
	bodies[0]->setWorldTransform(t);
	for (int i = 0; i < 4; i++)
	{
		btVector3 inertia;
		box.calculateLocalInertia(2, inertia);
		bodies.push_back(new btRigidBody(2, 0, &box, inertia));
		t.setOrigin(btVector3(btScalar(i), 0, 0));
		bodies[i + 1]->setWorldTransform(t);
	}
	for (int i = 0; i < bodies.size(); i++)
	{
		world.addRigidBody(bodies[i]);
	}

	btHingeConstraint hinge(*bodies[1], btVector3(-0.5f, 0, 0), btVector3(0, 0, 1));
	hinge.setLimit(-0.5f, 0.7f, 0.8f, 0.25f, 0.5f);
	hinge.enableAngularMotor(true, 1.5f, 2.0f);
	world.addConstraint(&hinge, true);

	btPoint2PointConstraint p2p(*bodies[1], *bodies[2], btVector3(0.5f, 0, 0), btVector3(-0.5f, 0, 0));
	world.addConstraint(&p2p, true);

	btTransform frameA, frameB;
	frameA.setIdentity();
	frameB.setIdentity();
	frameA.setOrigin(btVector3(0.5f, 0, 0));
	frameB.setOrigin(btVector3(-0.5f, 0, 0));
	btGeneric6DofSpring2Constraint spring2(*bodies[2], *bodies[3], frameA, frameB);
	spring2.setLinearLowerLimit(btVector3(0, -0.1f, 0));
	spring2.setLinearUpperLimit(btVector3(0, 0.1f, 0));
	spring2.setAngularLowerLimit(btVector3(0, 0, -0.3f));
	spring2.setAngularUpperLimit(btVector3(0, 0, 0.4f));
	spring2.enableSpring(1, true);
	spring2.setStiffness(1, 100.0f);
	spring2.setDamping(1, 0.5f);
	spring2.setEquilibriumPoint(1, 0.02f);
	world.addConstraint(&spring2, true);

	btHingeConstraint lockedHinge(*bodies[3], *bodies[4], frameA, frameB);
	lockedHinge.setLimit(0.25f, 0.25f);
	world.addConstraint(&lockedHinge, true);

	for (int i = 0; i < 10; i++)
	{
		world.stepSimulation(btScalar(1. / 240.), 0);
	}

	btDefaultSerializer serializer;
	world.serialize(&serializer);
	FILE* file = std::fopen(argv[1], "wb");
	if (!file || std::fwrite(serializer.getBufferPointer(), serializer.getCurrentBufferSize(), 1, file) != 1)
	{
		std::fprintf(stderr, "cannot write %s\n", argv[1]);
		return 1;
	}
	std::fclose(file);
	std::printf("wrote %s: %d bytes, %d bodies, %d constraints\n", argv[1], serializer.getCurrentBufferSize(), world.getNumCollisionObjects(), world.getNumConstraints());
	return 0;
}
