#!/usr/bin/env bash
# The test command (README, .ci/run): installs what is missing (tools/setup.sh --tests), builds
# everything once with clang, AddressSanitizer + UndefinedBehaviorSanitizer, libFuzzer's coverage
# and -Werror (tools/configure-ci.sh), runs every GoogleTest suite under CTest, then runs each
# libFuzzer target for a bounded time, two at a time.
#   FAPCAST_FUZZ_SECONDS=N  seconds per fuzz target (tools/configure-ci.sh's default; 0 skips the fuzz runs)
set -euo pipefail
cd "$(dirname "$0")/.."

# Each stage's wall time on standard error, so a slow CI run shows where its time went.
started=$SECONDS
stage() { echo "run-tests: $1 done after $((SECONDS - started)) s" >&2; }

bash tools/setup.sh --tests
stage "set-up"

jobs=$(nproc)
bash tools/configure-ci.sh
cmake --build build/ci -j "$jobs"
stage "build"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir build/ci --output-on-failure -j "$jobs" -LE fuzz
stage "tests"
if [ "${FAPCAST_FUZZ_SECONDS:-}" != 0 ]; then  # the default is tools/configure-ci.sh's
  ctest --test-dir build/ci --output-on-failure -j "$jobs" -L fuzz
  stage "fuzz runs"
fi
