// The scene toolkit as a game takes it: the installed Bullet::PlasticToolkit, compiled without exceptions. A 2 m
// steel cantilever (50 x 100 mm) of four plastic-hinge segments under a tip load of 1.05 Mp / L for 0.25 s, from a
// BeamSpec; the root yields alone (the next joint sees 0.79 Mp) and the work the joints booked is Mp times the root's
// rotation measured from its segment's orientation. A spec the toolkit refuses builds nothing and says why.
#include <cmath>
#include <cstdio>

#include "plastic/BeamBuilder.h"
#include "plastic/EnergyLedger.h"
#include "plastic/SolverSettings.h"

int main()
{
	plastic::StructureWorld structure;  // the toolkit's default solver settings (btDirectJointSolver, 1/240 s)
	btDiscreteDynamicsWorld& world = structure.world();
	btBoxShape supportShape(btVector3(0.1f, 0.1f, 0.1f));
	btRigidBody support(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &supportShape));
	world.addRigidBody(&support, 0, 0);

	plastic::BeamSpec bad;
	bad.segments = 0;
	const plastic::Beam refused(world, bad, &support);
	if (refused.errors().empty() || !refused.segments().empty())
	{
		std::printf("a beam of 0 segments was built\n");
		return 1;
	}
	std::printf("refused: %s\n", refused.errors().front().c_str());

	plastic::BeamSpec spec;
	spec.start_m = btVector3(0, 0, 0);
	spec.end_m = btVector3(2, 0, 0);
	spec.segments = 4;
	spec.joint.section = plastic::rectangle(0.05, 0.10);
	spec.joint.material = plastic::steel();
	spec.joint.method = plastic::JointMethod::PlasticHinge;
	const std::vector<std::string> errors = plastic::validate(spec);
	if (!errors.empty())
	{
		std::printf("refused: %s\n", errors.front().c_str());
		return 1;
	}
	plastic::Beam beam(world, spec, &support);
	const double mp = plastic::capacities(spec.joint.section, spec.joint.material).plastic_moment_y_nm;
	btRigidBody& root = *beam.segments().front();
	btRigidBody& tip = *beam.segments().back();
	const btQuaternion rootAtRest = root.getOrientation();
	plastic::PointLoad load(tip, btVector3(0, 0, btScalar(beam.segmentLength_m() / 2)), btVector3(0, btScalar(-1.05 * mp / 2.0), 0));
	for (int frame = 0; frame < 15; frame++)  // 0.25 s of 60 Hz frames, internal steps of the settings
	{
		for (int step = 0; step < 4; step++)
		{
			load.apply();
			structure.stepOnce();
			load.afterStep();
		}
	}
	const double rotation = (root.getOrientation() * rootAtRest.inverse()).getAngle();
	const double work = beam.plasticWork_j();
	std::printf("toolkit: Mp %.1f N m, root rotation %.4f rad, booked %.2f J, Mp x rotation %.2f J, load work %.2f J\n", mp, rotation, work,
				mp * rotation, load.work_j());
	if (!(rotation > 0.05) || !(std::fabs(work - mp * rotation) < 0.02 * mp * rotation) || !(work < load.work_j()))
	{
		std::printf("the books do not balance\n");
		return 1;
	}
	return 0;
}
