#!/usr/bin/env bash
# The whole test suite: install what is missing, build everything the tests need in build-test/ (preset test: tests,
# browser, benchmark programs, warnings as errors), run ctest (physics, the BT_THREADSAFE solver, rendering, runner,
# patch pipeline, install, reports), then the same suite under AddressSanitizer + UndefinedBehaviorSanitizer
# (ci/sanitize.sh, preset asan in build-asan/, without the OpenGL side and the pipeline). BP_SKIP_SANITIZERS=1 skips that.
# A subset after it: ctest --preset test -L physics (README, Tests).
set -euo pipefail
cd "$(dirname "$0")/.."
bash ci/deps.sh
export BP_DEPS_CHECKED=1
cmake --preset test
cmake --build --preset test
ctest --preset test -j"$(nproc)"
if [[ ${BP_SKIP_SANITIZERS:-0} != 1 ]]; then
	bash ci/sanitize.sh
fi
