#!/usr/bin/env bash
# Error against run time: builds the console runners, sweeps the Charpy test (ci/charpy_sweep.py,
# resumable) and writes report/charpy-sweep.csv, report/charpy-error-vs-runtime.png, report/REPORT.md;
# then the structures with textbook answers (ci/structures_report.py): report/STRUCTURES.md.
# Extra arguments go to the sweep (e.g. --jobs=1, --shard=1/2).
set -euo pipefail
cd "$(dirname "$0")/.."
bash ci/deps.sh
bash ci/configure.sh -DBP_BUILD_TESTS=OFF
cmake --build "${BUILD_DIR:-build}" --target charpy structures
python3 ci/charpy_sweep.py --runner="${BUILD_DIR:-build}/bin/charpy" --out=report/charpy-sweep.csv "$@"
python3 ci/charpy_report.py --csv=report/charpy-sweep.csv --out-dir=report --command="bash ci/report.sh $*"
python3 ci/structures_report.py --runner="${BUILD_DIR:-build}/bin/structures" --out=report/STRUCTURES.md --command="bash ci/report.sh"
