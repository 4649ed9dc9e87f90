#!/usr/bin/env bash
# The test suite under AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/, Debug with -O1).
# The OSMesa/GL side is left out (Mesa itself is not instrumented). Part of ci/test.sh; about 6 minutes on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
bash ci/deps.sh
flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined -O1 -g"
BUILD_DIR=build-asan bash ci/configure.sh -DBP_BUILD_TESTS=ON -DBP_BUILD_BROWSER=OFF -DBP_INSTALL=OFF -DCMAKE_BUILD_TYPE=Debug \
	-DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined"
cmake --build build-asan
cd build-asan
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	ctest --output-on-failure -j"$(nproc)" -E "^pipeline\." "$@"
