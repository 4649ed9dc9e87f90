#!/usr/bin/env bash
# Configures build/ with the main preset (CMakePresets.json: Ninja, unity build, Release, tests off). Extra arguments
# go to cmake, e.g. -DBULLET_SOURCE_DIR=/path/to/bullet3. The other trees: cmake --preset test|asan|double|bench.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset main "$@"
