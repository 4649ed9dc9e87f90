#!/usr/bin/env bash
# Error against run time: builds the console runners, sweeps the Charpy test (ci/charpy_sweep.py,
# resumable), runs the MuJoCo peer (ci/peer_sweep.py) and writes report/charpy-sweep.csv, report/charpy-peer.csv,
# report/charpy-error-vs-runtime.png, report/REPORT.md; then the friction sweep (ci/charpy_friction_sweep.py:
# report/charpy-friction.csv, report/FRICTION.md) and the structures with textbook answers
# (ci/structures_report.py): report/STRUCTURES.md.
# Extra arguments go to the sweep (e.g. --jobs=1, --shard=1/2).
set -euo pipefail
cd "$(dirname "$0")/.."
bash ci/deps.sh
cmake --preset main
cmake --build --preset main --target charpy structures
python3 ci/charpy_sweep.py --runner="build/bin/charpy" --out=report/charpy-sweep.csv "$@"
# the MuJoCo peer (pinned, in the build tree's venv) over the same frame steps, following the runner's parameters;
# without it (mujoco not installable here) the report is written without the peer
if peer_python="$(bash ci/peer_env.sh)"; then
	"$peer_python" ci/peer_sweep.py --runner=build/bin/charpy --out=report/charpy-peer.csv
else
	echo "ci/report.sh: no MuJoCo peer this time (see above); REPORT.md keeps no peer section" >&2
	rm -f report/charpy-peer.csv
fi
python3 ci/charpy_report.py --csv=report/charpy-sweep.csv --out-dir=report --command="bash ci/report.sh $*"
# The standard striker with friction beside the rigid-plastic model: report/charpy-friction.csv, report/FRICTION.md
python3 ci/charpy_friction_sweep.py --runner=build/bin/charpy --out-dir=report
python3 ci/structures_report.py --runner=build/bin/structures --out=report/STRUCTURES.md --command="bash ci/report.sh"
python3 ci/hardening_report.py --runner=build/bin/structures --out=report/HARDENING.md --command="bash ci/report.sh"
