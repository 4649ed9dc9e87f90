#!/usr/bin/env bash
# The game-settings comparison: builds build-bench/bin/game_settings (preset bench), runs every solver setting on the
# same structures (4- and 8-segment cantilevers, an L-frame), then build-bench/bin/game_settings_benchmarks (Google
# Benchmark: the cost per step of the means, 4 to 128 segments), and writes report/GAME_SETTINGS.md (about 3 min here).
set -euo pipefail
cd "$(dirname "$0")/.."
build=build-bench
cmake --preset bench
cmake --build --preset bench --target game_settings game_settings_benchmarks -j2
tables="$(mktemp)"
bench="$(mktemp)"
trap 'rm -f "$tables" "$bench"' EXIT
"$build/bin/game_settings" --out="$tables" 2>/dev/null
"$build/bin/game_settings_benchmarks" --benchmark_min_time=0.5 --benchmark_repetitions=3 --benchmark_report_aggregates_only=true \
	--benchmark_out="$bench" --benchmark_out_format=json > /dev/null
python3 ci/game_settings_report.py --tables="$tables" --bench="$bench" --out=report/GAME_SETTINGS.md
