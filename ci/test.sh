#!/usr/bin/env bash
# The whole test suite: install what is missing, build everything the tests need, run ctest (physics, the
# BT_THREADSAFE solver, rendering, runner, patch pipeline, install, reports), then the same suite under
# AddressSanitizer + UndefinedBehaviorSanitizer (ci/sanitize.sh, without the OpenGL side).
set -euo pipefail
cd "$(dirname "$0")/.."
bash ci/deps.sh
bash ci/configure.sh -DBP_BUILD_TESTS=ON -DBP_BUILD_BROWSER=ON -DBP_BUILD_BENCHMARKS=ON -DBP_WARNINGS_AS_ERRORS=ON
cmake --build "${BUILD_DIR:-build}"
(cd "${BUILD_DIR:-build}" && ctest --output-on-failure -j"$(nproc)")
if [[ ${BP_SKIP_SANITIZERS:-0} != 1 ]]; then
	bash ci/sanitize.sh
fi
