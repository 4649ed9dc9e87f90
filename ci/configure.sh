#!/usr/bin/env bash
# Configures build/ (unity build, Release). Extra arguments go to cmake, e.g. -DBULLET_SOURCE_DIR=/path/to/bullet3.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B "${BUILD_DIR:-build}" -G Ninja -DBP_UNITY_BUILD=ON "$@"
