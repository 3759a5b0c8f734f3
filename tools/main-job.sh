#!/usr/bin/env bash
# The main job (README, first command). Installs what running needs (tools/setup.sh without
# --tests: no compiler for fuzzing, no Blender, Node or tshark), builds `fapcast`, and runs
# `fapcast say` with the default voice (built from the SYNTHETIC reference corpus on first use and
# cached), then (1) converts a real Xface .fap sample through every format fapcast writes
# (strict .fap, FBA bitstream and back, BVH, JSON) and (2) records a small SYNTHETIC reference
# corpus (espeak-ng speech, ICT-FaceKit markers: C3D + WAV + TextGrid + manifest), (3) builds its
# voice onto the generic ICT face and scores the retargeting by the paper's lip measures.
# Outputs land in out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
fapcast=build/release/cli/fapcast
mkdir -p out
"$fapcast" say "The quick brown fox jumps over the lazy dog." -o out/say.fap --wav-out out/say.wav --viseme
"$fapcast" fap info out/say.fap
sample=tests/data/xface/joy.fap
"$fapcast" fap info "$sample"
"$fapcast" fap convert "$sample" -o out/joy.strict.fap
"$fapcast" encode "$sample" -o out/joy.fba --quant 1
"$fapcast" decode out/joy.fba -o out/joy.decoded.fap
"$fapcast" fap info out/joy.fba
"$fapcast" export "$sample" -o out/joy.bvh
"$fapcast" export "$sample" -o out/joy.json
"$fapcast" corpus record-reference -q -o out/reference-corpus --seed 1
"$fapcast" voice build -q out/reference-corpus -o out/reference.fapv
"$fapcast" voice info out/reference.fapv
"$fapcast" eval retarget -q out/reference.fapv
ls -l out/ | head -30
