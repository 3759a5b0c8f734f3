#!/usr/bin/env bash
# Runs one libFuzzer target for longer than CI does:  tools/run-fuzz.sh NAME [SECONDS]
# e.g. tools/run-fuzz.sh fap_text_fuzz 600. New inputs go to build/fuzz/tests/fuzz-scratch/NAME;
# a crash leaves crash-* in the current directory: turn it into a named regression test.
set -euo pipefail
cd "$(dirname "$0")/.."
name=${1:?usage: tools/run-fuzz.sh NAME [SECONDS]}
seconds=${2:-300}
bash tools/setup.sh --tests
cmake -S . -B build/fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DFAPCAST_FUZZ=ON -DFAPCAST_TESTS=OFF >/dev/null
cmake --build build/fuzz --target "$name"
mkdir -p "build/fuzz/tests/fuzz-scratch/$name"
"build/fuzz/tests/$name" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 \
  "build/fuzz/tests/fuzz-scratch/$name" "tests/fuzz/corpus/$name"
