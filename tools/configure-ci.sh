#!/usr/bin/env bash
# Configures build/ci, the one build the test command (tools/run-tests.sh) and the longer fuzz runs
# (tools/run-fuzz.sh) share: clang, AddressSanitizer + UndefinedBehaviorSanitizer and libFuzzer's
# coverage on every library, -Werror, the GoogleTest suites, the benchmarks and the fuzz targets.
# One build serves suites and fuzz targets, so the libraries compile once (clang compiles them in
# about two thirds of GCC's time; tools/build.sh's release build stays GCC).
#   FAPCAST_FUZZ_SECONDS=N  seconds each fuzz target runs as a CTest test (default 3)
set -euo pipefail
cd "$(dirname "$0")/.."
# -O1 -g1: sanitizers want some optimisation for speed and line tables for their reports; full
# debug info only costs build time. The suites' own code builds at -O0 (tests/CMakeLists.txt).
# A unity build (each target's sources compiled a few to a translation unit: the headers are
# parsed once per batch, not once per file) and lld for the links: spec/testing.md has the figures.
cmake -S . -B build/ci -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
  -DCMAKE_UNITY_BUILD=ON -DCMAKE_EXE_LINKER_FLAGS=-fuse-ld=lld \
  -DFAPCAST_SANITIZE=ON -DFAPCAST_FUZZ=ON -DFAPCAST_WERROR=ON \
  -DFAPCAST_TESTS=ON -DFAPCAST_BENCH=ON -DFAPCAST_TEST_CODE_OPTIONS=-O0 \
  -DFAPCAST_FUZZ_SECONDS="${FAPCAST_FUZZ_SECONDS:-3}" >/dev/null
