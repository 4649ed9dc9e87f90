// Steps a world with a plastic hinge (a patched API) and a portal frame under btDirectJointSolver through the
// installed Bullet, then lists the shared Bullet libraries the process has loaded (none when linked statically).
#include <btBulletDynamicsCommon.h>
#include <link.h>
#include <cmath>
#include <cstdio>
#include <cstring>

static int printBulletLibrary(dl_phdr_info* info, size_t, void* count)
{
	const char* name = info->dlpi_name;
	if (name != nullptr && (std::strstr(name, "libBullet") != nullptr || std::strstr(name, "libLinearMath") != nullptr))
	{
		std::printf("loaded: %s\n", name);
		++*static_cast<int*>(count);
	}
	return 0;
}

// btDirectJointSolver as a user constructs it, on a closed frame: a portal of 2 m columns and a 2 m beam, each in two
// 10 kg segments, fixed at both bases, plastic hinges (Mp = 2500 N m) at every joint, zero gravity, a horizontal load
// at the left knee. Plastic analysis: the sway mechanism (hinges at the bases and the knees) at H h = 4 Mp, 5000 N.
// Returns how far the left knee moves in 1 s under loadRatio times that (-1 if the solver fell back).
static double portalSway(double loadRatio)
{
	btDefaultCollisionConfiguration configuration;
	btCollisionDispatcher dispatcher(&configuration);
	btDbvtBroadphase broadphase;
	btDirectJointSolver solver;
	btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
	world.setGravity(btVector3(0, 0, 0));
	const btScalar mp = 2500;
	btBoxShape column(btVector3(btScalar(0.05), btScalar(0.5), btScalar(0.05)));
	btBoxShape beam(btVector3(btScalar(0.5), btScalar(0.05), btScalar(0.05)));
	// left column, beam, right column (from its top), each two segments; centres in the frame's plane
	const btVector3 centres[6] = {btVector3(0, btScalar(0.5), 0), btVector3(0, btScalar(1.5), 0), btVector3(btScalar(0.5), 2, 0),
								  btVector3(btScalar(1.5), 2, 0), btVector3(2, btScalar(1.5), 0), btVector3(2, btScalar(0.5), 0)};
	btRigidBody* segments[6];
	for (int i = 0; i < 6; i++)
	{
		btCollisionShape* shape = i == 2 || i == 3 ? static_cast<btCollisionShape*>(&beam) : static_cast<btCollisionShape*>(&column);
		btVector3 inertia;
		shape->calculateLocalInertia(10, inertia);
		btRigidBody::btRigidBodyConstructionInfo info(10, nullptr, shape, inertia);
		info.m_startWorldTransform.setOrigin(centres[i]);
		segments[i] = new btRigidBody(info);
		segments[i]->setActivationState(DISABLE_DEACTIVATION);
		world.addRigidBody(segments[i]);
	}
	// the joints in world coordinates: base-left, column-left, knee-left, mid-span, knee-right, column-right, base-right
	const btVector3 pivots[7] = {btVector3(0, 0, 0), btVector3(0, 1, 0), btVector3(0, 2, 0), btVector3(1, 2, 0), btVector3(2, 2, 0), btVector3(2, 1, 0), btVector3(2, 0, 0)};
	const btVector3 axis(0, 0, 1);
	btPlasticHingeConstraint* joints[7];
	joints[0] = new btPlasticHingeConstraint(*segments[0], pivots[0] - centres[0], axis);
	for (int i = 1; i < 6; i++)
		joints[i] = new btPlasticHingeConstraint(*segments[i - 1], *segments[i], pivots[i] - centres[i - 1], pivots[i] - centres[i], axis, axis);
	joints[6] = new btPlasticHingeConstraint(*segments[5], pivots[6] - centres[5], axis);
	for (btPlasticHingeConstraint* joint : joints)
	{
		joint->setPlasticMoment(mp);
		world.addConstraint(joint, true);
	}
	const btScalar load = btScalar(loadRatio) * 4 * mp / 2;
	const btVector3 knee = pivots[2] - centres[1];
	const btScalar start = (segments[1]->getCenterOfMassTransform() * knee).x();
	for (int k = 0; k < 240; k++)
	{
		segments[1]->applyForce(btVector3(load, 0, 0), segments[1]->getCenterOfMassTransform().getBasis() * knee);
		world.stepSimulation(btScalar(1.0 / 240.0), 0);
	}
	const double sway = double((segments[1]->getCenterOfMassTransform() * knee).x() - start);
	// the sway mechanism: the bases and knees turned, the column and mid-span joints did not
	bool mechanism = true;
	for (int i = 0; i < 7; i++)
		mechanism = mechanism && ((joints[i]->getCurrentPlasticRotation() > 1e-3) == (loadRatio > 1 && (i == 0 || i == 2 || i == 4 || i == 6)));
	const int fallbacks = solver.getNumFallbacks();
	for (btPlasticHingeConstraint* joint : joints)
	{
		world.removeConstraint(joint);
		delete joint;
	}
	for (btRigidBody* body : segments)
	{
		world.removeRigidBody(body);
		delete body;
	}
	return fallbacks == 0 && mechanism ? sway : std::nan("");  // NaN fails every check below
}

int main()
{
	const double holds = portalSway(0.9), sways = portalSway(1.1);
	std::printf("portal frame under btDirectJointSolver: the knee moves %g m at 0.9 of the sway collapse load, %g m at 1.1\n", holds, sways);
	if (!(std::fabs(holds) < 1e-3 && sways > 0.05))
		return 1;

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
	std::printf("plastic rotation %g rad, absorbed %g J\n", double(hinge.getCurrentPlasticRotation()), double(hinge.getAbsorbedEnergy()));

	int loaded = 0;
	dl_iterate_phdr(printBulletLibrary, &loaded);
	if (loaded == 0)
		std::printf("loaded: no shared Bullet library\n");
	return hinge.getCurrentPlasticRotation() > 0 && hinge.getAbsorbedEnergy() > 0 ? 0 : 1;
}
