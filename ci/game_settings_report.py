#!/usr/bin/env python3
"""The last section of report/GAME_SETTINGS.md: the cost per internal step from Google Benchmark's JSON.

  ci/game_settings_report.py BENCHMARK_JSON   (prints markdown; ci/game_settings.sh writes the report)

The JSON is build-bench/bin/game_settings_benchmarks' --benchmark_out (tests/benchmarks/game_settings_benchmarks.cpp),
with --benchmark_repetitions and --benchmark_report_aggregates_only: the medians make the table.
"""
import json
import sys


def main():
    if len(sys.argv) != 2:
        raise SystemExit(__doc__)
    runs = json.load(open(sys.argv[1]))["benchmarks"]
    print("\n## Cost per internal step (Google Benchmark, `build-bench/bin/game_settings_benchmarks`)\n")
    print("The plastic-hinge cantilever held at 0.9 Mp / L, 1/240 s, after one second to its steady state: sequential")
    print("impulse at 10 iterations and btDirectJointSolver at 4 to 128 segments, sequential impulse at 1000 iterations and")
    print("btMLCPSolver + Dantzig (dense, cubic in the rows) at 4 to 32; median of 3 repetitions of at least 0.5 s. CPU time")
    print("is the steadier figure on a shared machine. **per segment**: CPU us/step / segments; **x on doubling**: CPU time")
    print("against the same solver at half the segments (2.0: linear in the joints). **factorizations** and **active-set it.**:")
    print("btDirectJointSolver's per timed step; **fallbacks**: calls solved by sequential impulse instead, over the whole run.\n")
    print("| solver | segments | CPU us/step | wall us/step | per segment | x on doubling | factorizations | active-set it. | fallbacks |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    names = {"si_10_iterations": "sequential impulse, 10 it (upstream)", "si_1000_iterations": "sequential impulse, 1000 it",
             "mlcp_dantzig": "btMLCPSolver + Dantzig", "direct": "btDirectJointSolver (toolkit default)"}
    cpu = {}
    rows = []
    for r in runs:
        if r.get("aggregate_name") != "median":
            continue
        _, kind, segments = r["run_name"].split("/")
        scale = {"ns": 1e-3, "us": 1.0, "ms": 1e3}[r["time_unit"]]
        n = int(segments)
        cpu[(kind, n)] = r["cpu_time"] * scale
        rows.append((kind, n, r["cpu_time"] * scale, r["real_time"] * scale, r))
    for kind, n, c, w, r in rows:
        half = cpu.get((kind, n // 2))
        doubling = f"{c / half:.2f}" if half else ""
        counters = [f"{r[k]:.2f}" if k in r else "" for k in ("factorizations_per_step", "active_set_iterations_per_step")]
        print(f"| {names.get(kind, kind)} | {n} | {c:.1f} | {w:.1f} | {c / n:.2f} | {doubling} | {counters[0]} | {counters[1]} | {r.get('fallbacks', 0):.0f} |")
    pairs = sorted(n for kind, n in cpu if kind == "direct" and ("si_10_iterations", n) in cpu)
    if pairs:
        print("\nbtDirectJointSolver against upstream's sequential impulse at 10 iterations (CPU us/step, the table above):\n")
        print("| segments | sequential impulse, 10 it | btDirectJointSolver | direct / SI |")
        print("| --- | --- | --- | --- |")
        for n in pairs:
            si, direct = cpu[("si_10_iterations", n)], cpu[("direct", n)]
            print(f"| {n} | {si:.1f} | {direct:.1f} | {direct / si:.2f} |")


if __name__ == "__main__":
    main()
