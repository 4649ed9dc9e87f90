#!/usr/bin/env bash
# Numerical stability matrix: builds the console runner in single precision (build/) and double
# precision (build-double/, BT_USE_DOUBLE_PRECISION), runs every case x method 1-8 (ci/stability.py,
# resumable) and writes report/stability.csv and report/STABILITY.md. Extra arguments go to the script.
set -euo pipefail
cd "$(dirname "$0")/.."
bash ci/deps.sh
build="${BUILD_DIR:-build}"
bash ci/configure.sh -DBP_BUILD_TESTS=OFF
cmake --build "$build" --target charpy
BUILD_DIR=build-double bash ci/configure.sh -DBP_BUILD_TESTS=OFF -DBP_BUILD_BROWSER=OFF -DBP_USE_DOUBLE_PRECISION=ON
cmake --build build-double --target charpy
python3 ci/stability.py --runner="$build/bin/charpy" --runner-double=build-double/bin/charpy --out-dir=report \
	--command="bash ci/stability.sh $*" "$@"
