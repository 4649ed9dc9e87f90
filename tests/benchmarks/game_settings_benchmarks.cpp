// Per-step cost of the game-settings means on a cantilever of plastic hinges held at 0.9 of its collapse load
// (the steady state a game spends most frames in): Bullet's sequential impulse at 10 and 1000 iterations against
// btMLCPSolver + Dantzig (the toolkit default), 4 to 32 segments, 1/240 s. ci/game_settings.sh adds the table to
// report/GAME_SETTINGS.md.
#include <benchmark/benchmark.h>

#include "BeamBuilder.h"
#include "EnergyLedger.h"
#include "SolverSettings.h"

using namespace plastic;

namespace
{
void stepCantilever(benchmark::State& state, SolverKind kind, int iterations)
{
	WorldSolverSettings settings;
	settings.solver = kind;
	settings.iterations = iterations;
	StructureWorld structure(settings);
	btBoxShape supportShape(btVector3(0.1f, 0.1f, 0.1f));
	btRigidBody support(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &supportShape));
	support.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(-0.1f, 0, 0)));
	structure.world().addRigidBody(&support, 0, 0);
	{
		BeamSpec spec;
		spec.end_m = btVector3(2, 0, 0);
		spec.segments = int(state.range(0));
		spec.section = rectangle(0.05, 0.10);
		spec.material = steel();
		Beam beam(structure.world(), spec, &support);
		const double mp = capacities(spec.section, spec.material).plastic_moment_y_nm;
		PointLoad load(*beam.segments().back(), btVector3(0, 0, btScalar(beam.segmentLength_m() / 2)), btVector3(0, btScalar(-0.9 * mp / 2), 0));
		const double step_s = settings.internal_step_s;
		for (int i = 0; i < 240; i++)  // one second to the steady state
		{
			load.apply();
			structure.world().stepSimulation(btScalar(step_s), 0);
		}
		for (auto _ : state)
		{
			load.apply();
			structure.world().stepSimulation(btScalar(step_s), 0);
		}
		state.counters["segments"] = double(spec.segments);
		state.counters["mlcp_fallbacks"] = double(structure.solverFallbacks());
	}
	structure.world().removeRigidBody(&support);
}
}  // namespace

BENCHMARK_CAPTURE(stepCantilever, si_10_iterations, SolverKind::SequentialImpulse, 10)->Arg(4)->Arg(8)->Arg(16)->Arg(32);
BENCHMARK_CAPTURE(stepCantilever, si_1000_iterations, SolverKind::SequentialImpulse, 1000)->Arg(4)->Arg(8)->Arg(16)->Arg(32);
BENCHMARK_CAPTURE(stepCantilever, mlcp_dantzig, SolverKind::MlcpDantzig, 10)->Arg(4)->Arg(8)->Arg(16)->Arg(32);

BENCHMARK_MAIN();
