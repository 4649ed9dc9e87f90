// Per-step cost of plastic joints against the upstream joints they build on, scaling in the number of
// joints, and memory per joint. Run by ci/bench.sh, which writes report/BENCHMARKS.md.
#include <benchmark/benchmark.h>

#include <atomic>
#include <cstdlib>

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

void stepScene(benchmark::State& state, JointKind kind)
{
	const int joints = int(state.range(0));
	btAlignedAllocSetCustom(countingAlloc, countingFree);
	const long long before = gAllocatedBytes;
	JointScene scene(kind, joints);
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
}  // namespace

#ifndef BP_UPSTREAM_ONLY
BENCHMARK_CAPTURE(stepScene, plastic_hinge_idle, JointKind::PlasticHingeIdle)->Arg(1)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000);
BENCHMARK_CAPTURE(stepScene, plastic_hinge_yielding, JointKind::PlasticHingeYielding)->Arg(1)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000);
BENCHMARK_CAPTURE(stepScene, elastic_plastic, JointKind::ElasticPlastic)->Arg(1)->Arg(100);
BENCHMARK_CAPTURE(stepScene, elastic_plastic2, JointKind::ElasticPlastic2)->Arg(1)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000);
#endif
BENCHMARK_CAPTURE(stepScene, hinge_locked, JointKind::HingeLocked)->Arg(1)->Arg(100)->Arg(10000);
BENCHMARK_CAPTURE(stepScene, hinge_motor, JointKind::HingeMotor)->Arg(1)->Arg(100)->Arg(1000)->Arg(10000);
BENCHMARK_CAPTURE(stepScene, fixed_breakable, JointKind::FixedBreakable)->Arg(1)->Arg(100);
BENCHMARK_CAPTURE(stepScene, spring, JointKind::Spring)->Arg(1)->Arg(100);
BENCHMARK_CAPTURE(stepScene, spring2, JointKind::Spring2)->Arg(1)->Arg(100)->Arg(10000);

BENCHMARK_MAIN();
