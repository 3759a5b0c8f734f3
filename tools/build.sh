#!/usr/bin/env bash
# Installs what running needs (tools/setup.sh, no test tools) and builds an optimised `fapcast`
# into build/release/cli/fapcast.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release -DFAPCAST_TESTS=OFF >/dev/null
# The compiler's output goes to a log (GCC 12 prints false -Wrestrict warnings at -O3); shown on failure.
if ! cmake --build build/release -j "$(nproc)" --target fapcast >build/release/build.log 2>&1; then
  cat build/release/build.log >&2
  exit 1
fi
