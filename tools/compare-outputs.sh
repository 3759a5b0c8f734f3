#!/usr/bin/env bash
# Behaviour unchanged? Builds `fapcast` at BASE_REV and from the working tree (Release, no tests,
# only the executable), runs the same fixed scenario with each binary in its own scratch directory
# with its own voice cache, and compares the sha256 of every output:
#   output  base  new  same|DIFFERENT
# Exit 0 when every output is the same, 1 when any differs (or a side fails to produce it).
#   tools/compare-outputs.sh [BASE_REV [NEW_REV]]
# BASE_REV defaults to `git merge-base HEAD main`; NEW_REV (a commit) builds that revision in a
# worktree of its own (build/compare/src-next/, reused and moved to each NEW_REV, so its build
# build/compare/next/ stays incremental) instead of the working tree, which may then change.
#   FAPCAST_COMPARE_NEW_EXE=PATH  use this executable as the new side instead of building the
#                                 tree (to check the script: the base's own binary must say same)
# Build trees live under build/compare/ and are reused: base-<rev>/ (from a detached worktree
# src-<rev>/ of BASE_REV) and new/ (this tree). Scenario outputs: build/compare/run/{base,new}/.
# When a command's arguments change shape, change scenario_new only: scenario_base stays as the
# base revision's command line.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
base_rev=$(git rev-parse --short "${1:-$(git merge-base HEAD main)}")
new_rev=${2:+$(git rev-parse --short "$2")}
work=$root/build/compare
mkdir -p "$work"

# build SRC_DIR BUILD_DIR: configure once (Release, FAPCAST_TESTS=OFF) and build the executable.
build() {
  local src=$1 dir=$2
  if [ ! -f "$dir/CMakeCache.txt" ]; then
    cmake -S "$src" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DFAPCAST_TESTS=OFF >/dev/null
  fi
  if ! cmake --build "$dir" -j 2 --target fapcast >"$dir/build.log" 2>&1; then
    tail -n 40 "$dir/build.log" >&2
    echo "compare-outputs: the build in $dir failed (log: $dir/build.log)" >&2
    exit 1
  fi
}
# The executable inside a build tree, wherever the tree's layout puts it.
exe_in() {
  local f
  for f in "$1/cli/fapcast" "$1/tools/fapcast"; do
    if [ -x "$f" ]; then echo "$f"; return; fi
  done
  echo "compare-outputs: no fapcast executable under $1" >&2
  exit 1
}

base_src=$work/src-$base_rev
if [ ! -d "$base_src" ]; then
  git worktree add --detach "$base_src" "$base_rev" >/dev/null 2>&1
fi
build "$base_src" "$work/base-$base_rev"
base_exe=$(exe_in "$work/base-$base_rev")
if [ -n "${FAPCAST_COMPARE_NEW_EXE:-}" ]; then
  new_exe=$(realpath "$FAPCAST_COMPARE_NEW_EXE")
elif [ -n "$new_rev" ]; then
  if [ ! -d "$work/src-next" ]; then
    git worktree add --detach "$work/src-next" "$new_rev" >/dev/null 2>&1
  else
    git -C "$work/src-next" checkout -q --detach "$new_rev"
  fi
  build "$work/src-next" "$work/next"
  new_exe=$(exe_in "$work/next")
else
  build "$root" "$work/new"
  new_exe=$(exe_in "$work/new")
fi

# Inputs both sides read (from this tree, so the sides differ only in the binary).
inputs=$work/run/inputs
rm -rf "$work/run"
mkdir -p "$inputs"
ict=$root/data/ict-facekit/generic_neutral_mesh.obj
# A specific face for `adapt` and `voice retarget`: the generic one stretched and moved.
awk '/^v / { printf "v %.6f %.6f %.6f\n", $2 * 1.1, $3 * 1.05 + 0.2, $4 * 0.98; next } { print }' \
  "$ict" >"$inputs/specific.obj"
xface=$root/tests/data/xface
text="The quick brown fox jumps over the lazy dog."

# The scenario, one command line per step; $F is the binary, the working directory the side's
# scratch directory (relative paths only, so nothing of the directory lands in an output).
scenario_base() {
  $F corpus record-reference -q -o corpus --count 40 --seed 3
  $F voice build -q corpus -o voice.fapv
  $F say -q "$text" --voice voice.fapv -o say.fap --wav say.wav --viseme --expression joy:40
  $F say -q "$text" --voice voice.fapv -o say.fba --expression surprise:30,fear:10
  $F say -q "$text" --voice voice.fapv -o say.glb --wav say_glb.wav --expression anger:25
  $F say -q "$text" --voice voice.fapv -o say.json --fps 30 --beta 0 --max-active 0
  $F say -q "Hello there." -o say_default_voice.fap --wav say_default_voice.wav
  $F animate -q --wav corpus/utt0007.wav --align corpus/utt0007.TextGrid --voice voice.fapv \
    -o animate.fap --viseme --expression sadness:20
  $F animate -q --wav corpus/utt0011.wav --align corpus/utt0011.TextGrid --voice voice.fapv -o animate.bvh
  local s
  for s in joy anger beg; do
    $F encode "$xface/$s.fap" -o "enc_$s.fba"
    $F decode "enc_$s.fba" -o "dec_$s.fap"
  done
  $F encode "$xface/fear.fap" -o enc_fear_archive.fba --archive --quant 2
  $F decode enc_fear_archive.fba -o dec_fear_archive.fap
  $F encode say.fap -o enc_say.fba
  $F decode say.fba -o dec_say.fap
  $F fap convert "$xface/pride.fap" conv_pride_strict.fap
  $F fap convert "$xface/hate.fap" conv_hate_69.fap --dialect 69
  $F fap info say.fba >fap_info_say.txt
  $F export say.fap -o export_say.bvh
  $F export say.fap -o export_say.json --sample-rate 22050
  $F export "$xface/disgust.fap" -o export_disgust.bvh
  $F eval retarget -q voice.fapv >eval_retarget.txt
  $F eval synth -q --voice voice.fapv --count 3 --json eval_synth.json --plots eval_plots >eval_synth.txt
  $F expressions -o expressions_obj
  $F expressions -o expressions.glb --fps 10 --seconds 0.3
  $F adapt --generic "$ict" --specific "$inputs/specific.obj" --targets expressions_obj -o adapted
  $F voice retarget voice.fapv --generic "$ict" --specific "$inputs/specific.obj" -o voice_retarget.fapv \
    >voice_retarget.txt
  $F say -q "$text" --voice voice_retarget.fapv -o say_retargeted_voice.fap
  $F render say.glb -o render --width 96 --every 20
}
scenario_new() {
  $F corpus record-reference -q -o corpus --count 40 --seed 3
  $F voice build -q corpus -o voice.fapv
  $F say -q "$text" --voice voice.fapv -o say.fap --wav-out say.wav --viseme --expression joy:40
  $F say -q "$text" --voice voice.fapv -o say.fba --expression surprise:30,fear:10
  $F say -q "$text" --voice voice.fapv -o say.glb --wav-out say_glb.wav --expression anger:25
  $F say -q "$text" --voice voice.fapv -o say.json --fps 30 --beta 0 --max-active 0
  $F say -q "Hello there." -o say_default_voice.fap --wav-out say_default_voice.wav
  $F animate -q corpus/utt0007.wav corpus/utt0007.TextGrid --voice voice.fapv \
    -o animate.fap --viseme --expression sadness:20
  $F animate -q corpus/utt0011.wav corpus/utt0011.TextGrid --voice voice.fapv -o animate.bvh
  local s
  for s in joy anger beg; do
    $F encode "$xface/$s.fap" -o "enc_$s.fba"
    $F decode "enc_$s.fba" -o "dec_$s.fap"
  done
  $F encode "$xface/fear.fap" -o enc_fear_archive.fba --archive --quant 2
  $F decode enc_fear_archive.fba -o dec_fear_archive.fap
  $F encode say.fap -o enc_say.fba
  $F decode say.fba -o dec_say.fap
  $F fap convert "$xface/pride.fap" -o conv_pride_strict.fap
  $F fap convert "$xface/hate.fap" -o conv_hate_69.fap --dialect 69
  $F fap info say.fba >fap_info_say.txt
  $F export say.fap -o export_say.bvh
  $F export say.fap -o export_say.json --sample-rate 22050
  $F export "$xface/disgust.fap" -o export_disgust.bvh
  $F eval retarget -q voice.fapv >eval_retarget.txt
  # eval synth ships the say defaults (beta 0.1, cap 64); the base's defaults were beta 0, no cap.
  $F eval synth -q voice.fapv --count 3 --beta 0 --max-active 0 --json-out eval_synth.json \
    --plots-out eval_plots >eval_synth.txt
  # The report names the command that made it: map the new shape back, so the rest compares.
  sed -i 's|fapcast eval synth voice.fapv --count 3 --seed 2 --beta 0 --max-active 0|fapcast eval synth --voice voice.fapv --count 3 --seed 2|' \
    eval_synth.txt eval_synth.json
  $F expressions -o expressions_obj
  $F expressions -o expressions.glb --fps 10 --seconds 0.3
  $F adapt expressions_obj "$ict" "$inputs/specific.obj" -o adapted
  $F voice adapt voice.fapv "$ict" "$inputs/specific.obj" -o voice_retarget.fapv >voice_retarget.txt
  sed -i 's| components adapted over | components re-targeted over |' voice_retarget.txt  # the word is adaptation now
  $F say -q "$text" --voice voice_retarget.fapv -o say_retargeted_voice.fap
  $F render say.glb -o render --width 96 --every 20
}
# The new binary's voice build of the base side's corpus (the reader, not the recorder, compared).
cross_new_on_base_corpus() {
  (cd "$work/run/base" && F=$new_exe && SOURCE_DATE_EPOCH=1700000000 \
    $F voice build -q corpus -o "$work/run/cross/voice.fapv" >"$work/run/cross.log")
}

# run SIDE EXE: the scenario in run/SIDE with a voice cache of its own and a fixed build time.
run_side() {
  local side=$1 exe=$2
  mkdir -p "$work/run/$side/cache"
  (
    cd "$work/run/$side"
    export FAPCAST_CACHE_DIR=$work/run/$side/cache XDG_CACHE_HOME=$work/run/$side/cache/xdg
    export SOURCE_DATE_EPOCH=1700000000
    F=$exe
    set -e
    "scenario_$side"
  ) >"$work/run/$side.log" 2>&1 || {
    tail -n 20 "$work/run/$side.log" >&2
    echo "compare-outputs: the $side scenario failed (log: $work/run/$side.log)" >&2
    exit 1
  }
}
run_side base "$base_exe"
run_side new "$new_exe"
mkdir -p "$work/run/cross"
cross_new_on_base_corpus

# One row per output file; a directory of many files (the corpus, plots, frames) is one row
# whose hash covers every file's name and content, its differing files listed below it.
digest() {
  if [ -d "$1" ]; then
    (cd "$1" && find . -type f -print0 | sort -z | xargs -0 sha256sum) | sha256sum | cut -c1-16
  elif [ -f "$1" ]; then
    sha256sum "$1" | cut -c1-16
  else
    echo missing
  fi
}
status=0
row() {  # row NAME BASE_PATH NEW_PATH
  local b n verdict=same
  b=$(digest "$2")
  n=$(digest "$3")
  if [ "$b" = missing ] || [ "$b" != "$n" ]; then verdict=DIFFERENT; status=1; fi
  printf '%-34s %-16s %-16s %s\n' "$1" "$b" "$n" "$verdict"
  if [ "$verdict" = DIFFERENT ] && [ -d "$2" ] && [ -d "$3" ]; then
    diff <(cd "$2" && find . -type f -print0 | sort -z | xargs -0 sha256sum) \
         <(cd "$3" && find . -type f -print0 | sort -z | xargs -0 sha256sum) |
      grep '^[<>]' | awk '{print "    " $1 " " $3}' | sort -u -k2 | head -n 10
  fi
}
printf '%-34s %-16s %-16s %s\n' output "base $base_rev" "new ${new_rev:-tree}" verdict
for f in $(cd "$work/run/base" && ls -1 | grep -v '^cache$'); do
  row "$f" "$work/run/base/$f" "$work/run/new/$f"
done
for f in $(cd "$work/run/new" && ls -1 | grep -v '^cache$'); do
  [ -e "$work/run/base/$f" ] || row "$f" "$work/run/base/$f" "$work/run/new/$f"
done
row "cache/ (default voice)" "$work/run/base/cache" "$work/run/new/cache"
row "voice.fapv (new exe, base corpus)" "$work/run/base/voice.fapv" "$work/run/cross/voice.fapv"
exit $status
