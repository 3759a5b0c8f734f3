#!/usr/bin/env bash
# The main job (README, first command). Installs what is missing, builds `fapcast`, and runs the
# best end-to-end job the project has today. Synthesis (`fapcast say`) is not built yet
# (issues 3/7-5/7), so today the job reads the real Xface .fap samples, reports on them and
# converts them through every format fapcast writes: strict .fap, FBA bitstream and back, BVH, JSON.
# Outputs land in out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
fapcast=build/release/tools/fapcast
mkdir -p out
sample=tests/data/xface/joy.fap
"$fapcast" fap info "$sample"
"$fapcast" fap convert "$sample" out/joy.strict.fap
"$fapcast" encode "$sample" -o out/joy.fba --quant 1
"$fapcast" decode out/joy.fba -o out/joy.decoded.fap
"$fapcast" fap info out/joy.fba
"$fapcast" export "$sample" -o out/joy.bvh
"$fapcast" export "$sample" -o out/joy.json
ls -l out/
