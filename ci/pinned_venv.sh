# Sourced by the peers' environment scripts (ci/peer_env.sh, ci/opensees_env.sh): a venv with one pinned package,
# made once and reused. Exit 77 (ctest's skip code here) with a message naming the package when it cannot be made.

# pinned_venv_install SCRIPT VENV PACKAGE==VERSION PEER: makes VENV (python3 -m venv) and pip-installs the package
pinned_venv_install() {
	local script=$1 venv=$2 spec=$3 peer=$4
	mkdir -p "$(dirname "$venv")"
	if ! { [ -x "$venv/bin/python" ] || python3 -m venv "$venv" >&2; }; then
		echo "$script: cannot make a venv at $venv (python3 -m venv failed): the $peer peer is not installable here" >&2
		exit 77
	fi
	echo "$script: installing $spec into $venv" >&2
	if ! "$venv/bin/python" -m pip install --quiet --disable-pip-version-check "$spec" >&2; then
		echo "$script: pip could not install $spec: the $peer peer is not installable here" >&2
		exit 77
	fi
}

# pinned_venv_run VENV [CMD ARGS]: prints VENV's python, or runs CMD ARGS with it first on PATH (PEER_PYTHON set)
pinned_venv_run() {
	local venv=$1
	shift
	if [ $# -eq 0 ]; then
		echo "$venv/bin/python"
	else
		PEER_PYTHON="$venv/bin/python" PATH="$venv/bin:$PATH" exec "$@"
	fi
}
