#!/usr/bin/env bash
# Configures build/ (unity build, Release). Extra arguments go to cmake, e.g. -DBULLET_SOURCE_DIR=/path/to/bullet3.
set -euo pipefail
cd "$(dirname "$0")/.."
# A second build tree (build-asan, build-double) reuses the sdist build/ already downloaded.
archive="$PWD/build/_downloads/pybullet-3.2.7.tar.gz"
extra=()
if [[ ${BUILD_DIR:-build} != build && -f $archive ]]; then
	extra=(-DBULLET_ARCHIVE="$archive")
fi
cmake -S . -B "${BUILD_DIR:-build}" -G Ninja -DBP_UNITY_BUILD=ON "${extra[@]}" "$@"
