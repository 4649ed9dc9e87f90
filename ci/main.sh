#!/usr/bin/env bash
# The main job: install what is missing, fetch + verify + patch Bullet, build, run the Charpy test headless
# with default parameters and write its report (summary, JSON, per-step history) to build/charpy-report/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash ci/deps.sh
bash ci/configure.sh -DBP_BUILD_TESTS=OFF
cmake --build "${BUILD_DIR:-build}" --target charpy
out="${BUILD_DIR:-build}/charpy-report"
mkdir -p "$out"
bin="${BUILD_DIR:-build}/bin/charpy"
"$bin" --history="$out/history.csv" | tee "$out/summary.txt"
"$bin" --json > "$out/result.json.tmp" && mv "$out/result.json.tmp" "$out/result.json"
echo "report written to $out/ (summary.txt, result.json, history.csv)"
