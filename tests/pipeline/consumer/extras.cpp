// The other libraries upstream installs, through the installed headers and imported targets:
// a BulletSoftBody rope hanging from one end, and BulletInverseDynamics' holding torque of a pendulum.
#include <BulletInverseDynamics/MultiBodyTree.hpp>
#include <BulletSoftBody/btSoftBodyHelpers.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>
#include <btBulletDynamicsCommon.h>
#include <cmath>
#include <cstdio>

static double ropeEndHeight()
{
	btSoftBodyRigidBodyCollisionConfiguration configuration;
	btCollisionDispatcher dispatcher(&configuration);
	btDbvtBroadphase broadphase;
	btSequentialImpulseConstraintSolver solver;
	btSoftRigidDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
	world.setGravity(btVector3(0, -10, 0));
	world.getWorldInfo().m_gravity = world.getGravity();
	btSoftBody* rope = btSoftBodyHelpers::CreateRope(world.getWorldInfo(), btVector3(0, 0, 0), btVector3(1, 0, 0), 8, 1);
	world.addSoftBody(rope);
	for (int i = 0; i < 30; ++i)
		world.stepSimulation(btScalar(1.0 / 60.0), 0);
	const double height = double(rope->m_nodes[rope->m_nodes.size() - 1].m_x.y());
	world.removeSoftBody(rope);
	delete rope;
	return height;
}

// A 2 kg point 0.5 m from a revolute joint about z, horizontal, at rest: it takes m g r = 9.81 N m to hold.
static double holdingTorque()
{
	using namespace btInverseDynamics;
	MultiBodyTree tree;
	vec3 offset, axis, com;
	mat33 rotation, inertia;
	for (int i = 0; i < 3; ++i)
	{
		offset(i) = axis(i) = com(i) = 0;
		for (int j = 0; j < 3; ++j)
		{
			rotation(i, j) = i == j ? 1 : 0;
			inertia(i, j) = 0;
		}
	}
	axis(2) = 1;
	com(0) = 0.5;
	if (tree.addBody(0, -1, REVOLUTE, offset, rotation, axis, 2.0, com, inertia, 0, nullptr) != 0 || tree.finalize() != 0)
		return -1;
	vec3 gravity;
	gravity(0) = 0;
	gravity(1) = -9.81;
	gravity(2) = 0;
	tree.setGravityInWorldFrame(gravity);
	vecx q(1), u(1), dot_u(1), torque(1);
	q(0) = u(0) = dot_u(0) = 0;
	if (tree.calculateInverseDynamics(q, u, dot_u, &torque) != 0)
		return -1;
	return std::fabs(double(torque(0)));
}

int main()
{
	const double height = ropeEndHeight();
	const double torque = holdingTorque();
	std::printf("soft rope free end at y = %g m, inverse dynamics holding torque %g N m\n", height, torque);
	return height < -0.1 && std::fabs(torque - 9.81) < 1e-3 ? 0 : 1;
}
