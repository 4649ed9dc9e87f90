// Per-step cost of plastic joints against the upstream joints they build on, scaling in the number of
// joints, and memory per joint. Run by ci/bench.sh, which writes report/BENCHMARKS.md.
#include <benchmark/benchmark.h>

#include <atomic>
#include <cstdlib>
#include <memory>

#include "JointScene.h"
#include "LinearMath/btAlignedAllocator.h"

namespace
{
// Bytes Bullet allocates through btAlignedAlloc (constraints, bodies, solver pools), for memory per joint.
std::atomic<long long> gAllocatedBytes{0};
void* countingAlloc(size_t size)
{
	gAllocatedBytes += (long long)size;
	return std::malloc(size);
}
void countingFree(void* p) { std::free(p); }

void stepScene(benchmark::State& state, JointKind kind, bool splitIslands, bool directSolver = false)
{
	const int joints = int(state.range(0));
	btAlignedAllocSetCustom(countingAlloc, countingFree);
	const long long before = gAllocatedBytes;
	JointScene scene(kind, joints, splitIslands, directSolver);
	scene.step();  // the solver's pools grow on the first step
	const long long allocated = gAllocatedBytes - before;
	for (auto _ : state) scene.step();
	state.counters["joints"] = joints;
	state.counters["ns_per_joint_step"] = benchmark::Counter(double(joints) * state.iterations(),
															  benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
	// everything Bullet allocated for the scene (bodies, broadphase, solver pools), per joint
	state.counters["scene_bytes_per_joint"] = double(allocated) / joints;
	state.counters["constraint_bytes"] = double(JointScene::constraintSize(kind));
}

// One second (60 steps) of N four-box members breaking into pieces, island splitting on; time per step.
void breakingScene(benchmark::State& state, bool plastic)
{
	const int members = int(state.range(0));
	int broken = 0;
	for (auto _ : state)
	{
		state.PauseTiming();
		auto scene = std::make_unique<BreakingScene>(members, plastic);
		state.ResumeTiming();
		for (int i = 0; i < 60; i++) scene->step();
		state.PauseTiming();
		broken = 4 * members - scene->enabledJoints();
		scene.reset();
		state.ResumeTiming();
	}
	state.counters["joints"] = 4 * members;
	state.counters["broken_joints"] = broken;
	state.counters["s_per_step"] = benchmark::Counter(60.0 * state.iterations(), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
}  // namespace

#ifndef BP_UPSTREAM_ONLY
BENCHMARK_CAPTURE(stepScene, plastic_hinge_idle, JointKind::PlasticHingeIdle, false)->Arg(1)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000);
BENCHMARK_CAPTURE(stepScene, plastic_hinge_yielding, JointKind::PlasticHingeYielding, false)->Arg(1)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000);
BENCHMARK_CAPTURE(stepScene, elastic_plastic, JointKind::ElasticPlastic, false)->Arg(1)->Arg(100);
BENCHMARK_CAPTURE(stepScene, elastic_plastic2, JointKind::ElasticPlastic2, false)->Arg(1)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000);
// Bullet's default island splitting
BENCHMARK_CAPTURE(stepScene, plastic_hinge_idle_split, JointKind::PlasticHingeIdle, true)->Arg(1000)->Arg(10000);
BENCHMARK_CAPTURE(stepScene, plastic_hinge_yielding_split, JointKind::PlasticHingeYielding, true)->Arg(1000)->Arg(10000);
BENCHMARK_CAPTURE(stepScene, elastic_plastic2_split, JointKind::ElasticPlastic2, true)->Arg(1000)->Arg(10000);
BENCHMARK_CAPTURE(breakingScene, plastic_members, true)->Arg(1000)->Unit(benchmark::kMillisecond);
// the same scenes under btDirectJointSolver (one solver call: no island splitting)
BENCHMARK_CAPTURE(stepScene, plastic_hinge_idle_direct, JointKind::PlasticHingeIdle, false, true)->Arg(1)->Arg(100)->Arg(1000);
BENCHMARK_CAPTURE(stepScene, plastic_hinge_yielding_direct, JointKind::PlasticHingeYielding, false, true)->Arg(1)->Arg(100)->Arg(1000);
BENCHMARK_CAPTURE(stepScene, elastic_plastic2_direct, JointKind::ElasticPlastic2, false, true)->Arg(1)->Arg(100)->Arg(1000);
BENCHMARK_CAPTURE(stepScene, hinge_locked_direct, JointKind::HingeLocked, false, true)->Arg(1)->Arg(100)->Arg(1000);
#endif
BENCHMARK_CAPTURE(stepScene, hinge_locked, JointKind::HingeLocked, false)->Arg(1)->Arg(100)->Arg(1000)->Arg(10000);
BENCHMARK_CAPTURE(stepScene, hinge_motor, JointKind::HingeMotor, false)->Arg(1)->Arg(100)->Arg(1000)->Arg(10000);
BENCHMARK_CAPTURE(stepScene, fixed_breakable, JointKind::FixedBreakable, false)->Arg(1)->Arg(100);
BENCHMARK_CAPTURE(stepScene, spring, JointKind::Spring, false)->Arg(1)->Arg(100);
BENCHMARK_CAPTURE(stepScene, spring2, JointKind::Spring2, false)->Arg(1)->Arg(100)->Arg(1000)->Arg(10000);
BENCHMARK_CAPTURE(stepScene, hinge_locked_split, JointKind::HingeLocked, true)->Arg(1000)->Arg(10000);
BENCHMARK_CAPTURE(stepScene, hinge_motor_split, JointKind::HingeMotor, true)->Arg(1000)->Arg(10000);
BENCHMARK_CAPTURE(stepScene, spring2_split, JointKind::Spring2, true)->Arg(1000)->Arg(10000);
BENCHMARK_CAPTURE(breakingScene, upstream_members, false)->Arg(1000)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
