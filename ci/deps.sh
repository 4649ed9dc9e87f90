#!/usr/bin/env bash
# Installs what the build and tests need on Debian bookworm (run as root), skipping what is there.
# Once per CI run: a script that ran it exports BP_DEPS_CHECKED=1, and the scripts it calls skip it then.
set -euo pipefail
if [[ ${BP_DEPS_CHECKED:-0} == 1 ]]; then
	exit 0
fi
packages=(cmake ninja-build pkg-config quilt g++ python3 python3-pip python3-venv libgtest-dev libbenchmark-dev clang-format
	libosmesa6-dev libgl-dev mesa-common-dev)
missing=()
for p in "${packages[@]}"; do
	dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
	if [ "$(id -u)" != 0 ]; then
		echo "ci/deps.sh: missing Debian packages: ${missing[*]} -- run: sudo apt-get install ${missing[*]}" >&2
		exit 1
	fi
	echo "ci/deps.sh: installing ${missing[*]}"
	apt-get update -qq
	DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}" >/dev/null
fi
# pip downloads the pinned sdist; any python3 with pip will do (a pyenv one included)
python3 -m pip --version >/dev/null 2>&1 || { echo "ci/deps.sh: python3 has no pip: apt-get install python3-pip" >&2; exit 1; }
# the reports plot with matplotlib (from pip: Debian's python3-matplotlib is not seen by a pyenv python3)
# and the GUI text check reads PNGs with Pillow (a dependency of matplotlib; named for clarity)
python3 -c "import matplotlib, PIL" >/dev/null 2>&1 || {
	echo "ci/deps.sh: installing matplotlib and Pillow with pip"
	python3 -m pip install --quiet --disable-pip-version-check matplotlib pillow
}
