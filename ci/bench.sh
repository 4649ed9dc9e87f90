#!/usr/bin/env bash
# Benchmarks (Google Benchmark): builds joint_benchmarks, joint_benchmarks_unpatched and thread_benchmarks
# (BT_THREADSAFE) and city_benchmarks (the city's frames and runs, issue 24) in build-bench/ (preset bench: Release, no -Werror, no browser), runs them one after the other and
# writes report/BENCHMARKS.md (+ the raw JSON in report/benchmarks/).
set -euo pipefail
cd "$(dirname "$0")/.."
bash ci/deps.sh
build=build-bench
cmake --preset bench
cmake --build --preset bench --target joint_benchmarks joint_benchmarks_unpatched thread_benchmarks city_benchmarks
mkdir -p report/benchmarks
for b in joint_benchmarks joint_benchmarks_unpatched thread_benchmarks city_benchmarks; do
	"$build/bin/$b" --benchmark_out="report/benchmarks/$b.json.tmp" --benchmark_out_format=json --benchmark_repetitions=1 "$@"
	mv "report/benchmarks/$b.json.tmp" "report/benchmarks/$b.json"
done
python3 ci/bench_report.py report/benchmarks/joint_benchmarks.json report/benchmarks/joint_benchmarks_unpatched.json \
	report/BENCHMARKS.md "bash ci/bench.sh $*" report/benchmarks/thread_benchmarks.json
