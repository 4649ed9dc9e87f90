// The city's costs (issue 24) as benchmarks, not timed tests: a 60 Hz frame (four internal steps) of 100 buildings with
// 10 balls swinging at them, before the first impact, just in time against rigid (`idleFrame`); and the whole 3 s run
// after set-up, just in time against always jointed (`run`), and 1000 buildings with 10 hit just in time. Counters: the
// frames and internal steps timed, the simulated seconds per wall second (`real_time_factor`) and the plastic work.
// Ratios are taken between the rows of one run of this program (ci/bench.sh writes report/benchmarks/city_benchmarks.json).
#include <benchmark/benchmark.h>

#include <memory>

#include "City.h"

using namespace game;

namespace
{
CityParameters city(CityMode mode, int buildings)
{
	CityParameters p;
	p.mode = mode;
	p.buildings = buildings;
	p.hit = 10;
	return p;
}

// one frame before the first impact (the balls' release to 1.15 s; the first impact is at 1.246 s), the city built anew
// (untimed) when it gets there
void idleFrame(benchmark::State& state, CityMode mode)
{
	const CityParameters p = city(mode, int(state.range(0)));
	auto scene = std::make_unique<CityScene>(p);
	long frames = 0;
	for (auto _ : state)
	{
		scene->step();
		frames++;
		if (scene->time_s() > 1.15)
		{
			state.PauseTiming();
			scene = std::make_unique<CityScene>(p);
			state.ResumeTiming();
		}
	}
	state.counters["frames"] = double(frames);
	state.counters["internal_steps_per_frame"] = double(scene->result().internal_steps) / double(scene->result().frames);
	state.counters["real_time_factor"] = benchmark::Counter(double(frames) / p.building.frame_rate_hz, benchmark::Counter::kIsRate);
}

// the whole run (3 s, 180 frames) after set-up
void run(benchmark::State& state, CityMode mode)
{
	const CityParameters p = city(mode, int(state.range(0)));
	double plastic_j = 0, simulated_s = 0;
	for (auto _ : state)
	{
		state.PauseTiming();
		auto scene = std::make_unique<CityScene>(p);
		state.ResumeTiming();
		while (!scene->done()) scene->step();
		state.PauseTiming();
		plastic_j = scene->result().plastic_energy_j;
		simulated_s += scene->time_s();
		scene.reset();
		state.ResumeTiming();
	}
	state.counters["plastic_energy_J"] = plastic_j;
	state.counters["real_time_factor"] = benchmark::Counter(simulated_s, benchmark::Counter::kIsRate);
}
}  // namespace

BENCHMARK_CAPTURE(idleFrame, jit, CityMode::JustInTime)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(idleFrame, rigid, CityMode::Rigid)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(run, jit, CityMode::JustInTime)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(run, jointed, CityMode::Jointed)->Arg(100)->Unit(benchmark::kMillisecond)->Iterations(3);

BENCHMARK_MAIN();
