#!/usr/bin/env bash
# The test command (README, .ci/run): installs what is missing (tools/setup.sh --tests), builds
# everything with AddressSanitizer + UndefinedBehaviorSanitizer and -Werror, runs every GoogleTest
# suite under CTest, then builds the libFuzzer targets with clang and runs each for a bounded time.
#   FAPCAST_FUZZ_SECONDS=N  seconds per fuzz target (default 5; 0 skips the fuzz stage)
set -euo pipefail
cd "$(dirname "$0")/.."

# Each stage's wall time on standard error, so a slow CI run shows where its time went.
started=$SECONDS
stage() { echo "run-tests: $1 done after $((SECONDS - started)) s" >&2; }

bash tools/setup.sh --tests
stage "set-up"

jobs=$(nproc)
fuzz_seconds=${FAPCAST_FUZZ_SECONDS:-5}

# -g1: line tables are all a sanitizer report needs, and full debug info costs build time.
cmake -S . -B build/ci -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
  -DFAPCAST_SANITIZE=ON -DFAPCAST_WERROR=ON -DFAPCAST_TESTS=ON -DFAPCAST_BENCH=ON
cmake --build build/ci -j "$jobs"
stage "sanitizer build"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir build/ci --output-on-failure -j "$jobs"
stage "tests"

if [ "$fuzz_seconds" != 0 ]; then
  cmake -S . -B build/fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DCMAKE_CXX_COMPILER=clang++ -DFAPCAST_FUZZ=ON -DFAPCAST_TESTS=OFF -DFAPCAST_WERROR=ON \
    -DFAPCAST_FUZZ_SECONDS="$fuzz_seconds"
  cmake --build build/fuzz -j "$jobs" --target fapcast_fuzz_targets
  stage "fuzz build"
  ctest --test-dir build/fuzz --output-on-failure -L fuzz
  stage "fuzz runs"
fi
