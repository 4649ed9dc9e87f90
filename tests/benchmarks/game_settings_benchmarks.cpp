// Per-step cost of the game-settings means on a cantilever of plastic hinges held at 0.9 of its collapse load
// (the steady state a game spends most frames in), 1/240 s: Bullet's sequential impulse at 10 iterations and
// btDirectJointSolver (patch 0019, the toolkit default) at 4 to 128 segments, sequential impulse at 1000 iterations
// and btMLCPSolver + Dantzig (a dense solve, cubic in the rows) at 4 to 32. Counters per timed step: the direct
// solver's factorizations and active-set iterations; fallbacks to sequential impulse over the whole run (warm-up
// included) for both direct solvers. ci/game_settings.sh adds the table to report/GAME_SETTINGS.md.
#include <benchmark/benchmark.h>

#include "plastic/BeamBuilder.h"
#include "plastic/EnergyLedger.h"
#include "plastic/SolverSettings.h"

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
		spec.may_sleep = false;  // the cost of a loaded structure, not of a sleeping one
		spec.end_m = btVector3(2, 0, 0);
		spec.segments = int(state.range(0));
		spec.joint.section = rectangle(0.05, 0.10);
		spec.joint.material = steel();
		Beam beam(structure.world(), spec, &support);
		const double mp = capacities(spec.joint.section, spec.joint.material).plastic_moment_y_nm;
		PointLoad load(*beam.segments().back(), btVector3(0, 0, btScalar(beam.segmentLength_m() / 2)), btVector3(0, btScalar(-0.9 * mp / 2), 0));
		const double step_s = settings.internal_step_s;
		for (int i = 0; i < 240; i++)  // one second to the steady state
		{
			load.apply();
			structure.world().stepSimulation(btScalar(step_s), 0);
		}
		const auto* direct = dynamic_cast<const btDirectJointSolver*>(structure.world().getConstraintSolver());
		const int factorizations = direct ? direct->getNumFactorizations() : 0;
		const int activeSetIterations = direct ? direct->getNumActiveSetIterations() : 0;
		for (auto _ : state)
		{
			load.apply();
			structure.world().stepSimulation(btScalar(step_s), 0);
		}
		state.counters["segments"] = double(spec.segments);
		state.counters["fallbacks"] = double(structure.solverFallbacks());
		if (direct)
		{
			const double steps = double(state.iterations());
			state.counters["factorizations_per_step"] = double(direct->getNumFactorizations() - factorizations) / steps;
			state.counters["active_set_iterations_per_step"] = double(direct->getNumActiveSetIterations() - activeSetIterations) / steps;
		}
	}
	structure.world().removeRigidBody(&support);
}
}  // namespace

BENCHMARK_CAPTURE(stepCantilever, si_10_iterations, SolverKind::SequentialImpulse, 10)->RangeMultiplier(2)->Range(4, 128);
BENCHMARK_CAPTURE(stepCantilever, direct, SolverKind::DirectJoint, 10)->RangeMultiplier(2)->Range(4, 128);
BENCHMARK_CAPTURE(stepCantilever, si_1000_iterations, SolverKind::SequentialImpulse, 1000)->RangeMultiplier(2)->Range(4, 32);
BENCHMARK_CAPTURE(stepCantilever, mlcp_dantzig, SolverKind::MlcpDantzig, 10)->RangeMultiplier(2)->Range(4, 32);

BENCHMARK_MAIN();
