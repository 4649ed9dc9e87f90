#!/usr/bin/env bash
# The Python environment of the MuJoCo peer (ci/models/mujoco_charpy.py, ci/peer_sweep.py): a venv under the build
# tree with the pinned mujoco, made once and reused. Prints the venv's python on stdout.
#   bash ci/peer_env.sh            -> prints e.g. build/peer-venv/bin/python
#   bash ci/peer_env.sh CMD ARGS   -> runs CMD ARGS with that python first on PATH (PEER_PYTHON set)
# Exit 77 (ctest's skip code here) with a message naming the package when mujoco cannot be installed.
set -euo pipefail
cd "$(dirname "$0")/.."
. ci/pinned_venv.sh
MUJOCO_VERSION=4.0.0  # pinned; ci/models/mujoco_charpy.py MUJOCO_VERSION says the same
venv="${PEER_VENV:-build/peer-venv}"
python="$venv/bin/python"
have() { [ -x "$python" ] && "$python" -c "import mujoco, sys; sys.exit(mujoco.__version__ != '$MUJOCO_VERSION')" 2>/dev/null; }
if ! have; then
	pinned_venv_install ci/peer_env.sh "$venv" "mujoco==$MUJOCO_VERSION" MuJoCo
	have || { echo "ci/peer_env.sh: mujoco==$MUJOCO_VERSION installed but does not import" >&2; exit 77; }
fi
pinned_venv_run "$venv" "$@"
