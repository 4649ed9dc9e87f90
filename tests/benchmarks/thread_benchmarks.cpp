// The same joint scenes on btDiscreteDynamicsWorldMt (BT_THREADSAFE build): a pool of solvers for the islands
// (island splitting on) or btSequentialImpulseConstraintSolverMt for one large island (off), on 1 and 2 threads
// of upstream's default task scheduler. Run by ci/bench.sh; the speedups are in report/BENCHMARKS.md.
#include <benchmark/benchmark.h>

#include "JointScene.h"
#include "LinearMath/btThreads.h"

namespace
{
btITaskScheduler* scheduler()
{
	// kept for the life of the process (upstream's btTaskSchedulerDefault may crash in its destructor)
	static btITaskScheduler* s = btCreateDefaultTaskScheduler();
	return s;
}

void stepSceneThreads(benchmark::State& state, JointKind kind, bool splitIslands)
{
	const int joints = int(state.range(0)), threads = int(state.range(1));
	scheduler()->setNumThreads(threads);
	btSetTaskScheduler(scheduler());
	{
		JointScene scene(kind, joints, splitIslands);
		scene.step();
		for (auto _ : state) scene.step();
	}
	btSetTaskScheduler(btGetSequentialTaskScheduler());
	state.counters["joints"] = joints;
	state.counters["threads"] = threads;
}
}  // namespace

BENCHMARK_CAPTURE(stepSceneThreads, plastic_hinge_yielding_split, JointKind::PlasticHingeYielding, true)->Args({10000, 1})->Args({10000, 2})->UseRealTime();
BENCHMARK_CAPTURE(stepSceneThreads, plastic_hinge_yielding, JointKind::PlasticHingeYielding, false)->Args({10000, 1})->Args({10000, 2})->UseRealTime();
BENCHMARK_CAPTURE(stepSceneThreads, hinge_motor_split, JointKind::HingeMotor, true)->Args({10000, 1})->Args({10000, 2})->UseRealTime();
BENCHMARK_CAPTURE(stepSceneThreads, elastic_plastic2_split, JointKind::ElasticPlastic2, true)->Args({10000, 1})->Args({10000, 2})->UseRealTime();
BENCHMARK_CAPTURE(stepSceneThreads, elastic_plastic2, JointKind::ElasticPlastic2, false)->Args({10000, 1})->Args({10000, 2})->UseRealTime();

BENCHMARK_MAIN();
