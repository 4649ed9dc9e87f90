// Steps a world with a plastic hinge (a patched API) through the installed Bullet, then lists the shared
// Bullet libraries the process has loaded (none when linked statically).
#include <btBulletDynamicsCommon.h>
#include <link.h>
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
	std::printf("plastic rotation %g rad, absorbed %g J\n", double(hinge.getCurrentPlasticRotation()), double(hinge.getAbsorbedEnergy()));

	int loaded = 0;
	dl_iterate_phdr(printBulletLibrary, &loaded);
	if (loaded == 0)
		std::printf("loaded: no shared Bullet library\n");
	return hinge.getCurrentPlasticRotation() > 0 && hinge.getAbsorbedEnergy() > 0 ? 0 : 1;
}
