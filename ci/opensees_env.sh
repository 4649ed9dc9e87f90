#!/usr/bin/env bash
# The Python environment of the OpenSees peer (ci/models/opensees_cantilever.py): a venv under the build tree with the
# pinned openseespy, made once and reused. Prints the venv's python on stdout.
#   bash ci/opensees_env.sh            -> prints e.g. build/opensees-venv/bin/python
#   bash ci/opensees_env.sh CMD ARGS   -> runs CMD ARGS with that python first on PATH (PEER_PYTHON set)
# OPENSEES_VENV overrides the venv's folder. Exit 77 (ctest's skip code here) with a message naming the package
# when openseespy cannot be installed or does not import.
# openseespylinux's wheel ships libblas.so.3 and liblapack.so.3, but its liblapack does not find its libblas
# unless Debian's libblas3 is installed; ci/models/opensees_cantilever.py load_opensees() loads the wheel's libblas first,
# and the check below imports openseespy that way, so neither libblas3 nor liblapack3 is needed.
set -euo pipefail
cd "$(dirname "$0")/.."
. ci/pinned_venv.sh
OPENSEESPY_VERSION=3.7.1.2  # pinned; ci/models/opensees_cantilever.py OPENSEESPY_VERSION says the same
venv="${OPENSEES_VENV:-build/opensees-venv}"
python="$venv/bin/python"
check() {
	"$python" - "$OPENSEESPY_VERSION" <<-'EOF'
		import sys
		from importlib import metadata
		sys.path.insert(0, "ci/models")
		import opensees_cantilever as oc
		if metadata.version("openseespy") != sys.argv[1]:
		    sys.exit(f"openseespy {metadata.version('openseespy')} is installed, not {sys.argv[1]}")
		oc.load_opensees()  # import openseespy.opensees
	EOF
}
have() { [ -x "$python" ] && check >/dev/null 2>&1; }
if ! have; then
	pinned_venv_install ci/opensees_env.sh "$venv" "openseespy==$OPENSEESPY_VERSION" OpenSees
	if ! check >&2; then
		missing=""
		for p in libblas3 liblapack3; do
			dpkg -s "$p" >/dev/null 2>&1 || missing="$missing $p"
		done
		echo "ci/opensees_env.sh: openseespy==$OPENSEESPY_VERSION installed but does not import${missing:+ (not installed:$missing; apt-get install -y$missing may help)}" >&2
		exit 77
	fi
fi
pinned_venv_run "$venv" "$@"
