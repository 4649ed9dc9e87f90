#!/usr/bin/env bash
# Numerical stability matrix: builds the console runner in single precision (preset main, build/) and double
# precision (preset double, build-double/, BT_USE_DOUBLE_PRECISION), runs every case x method 1-8 (ci/stability.py,
# resumable) and writes report/stability.csv and report/STABILITY.md. Extra arguments go to the script.
set -euo pipefail
cd "$(dirname "$0")/.."
bash ci/deps.sh
cmake --preset main
cmake --build --preset main --target charpy
cmake --preset double
cmake --build --preset double
python3 ci/stability.py --runner=build/bin/charpy --runner-double=build-double/bin/charpy --out-dir=report \
	--command="bash ci/stability.sh $*" "$@"
