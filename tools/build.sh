#!/usr/bin/env bash
# Installs what is missing and builds an optimised `fapcast` into build/release/tools/fapcast.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release -DFAPCAST_TESTS=OFF >/dev/null
cmake --build build/release -j "$(nproc)" --target fapcast
