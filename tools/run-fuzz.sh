#!/usr/bin/env bash
# Runs libFuzzer targets for longer than CI does, outside CI:
#   tools/run-fuzz.sh NAME [SECONDS]     one target (default 300 s), e.g. tools/run-fuzz.sh fap_text_fuzz 600
#   tools/run-fuzz.sh --all SECONDS      every target, one at a time (nice -n 19), then a table of
#                                        executions, coverage and findings per target in
#                                        build/ci/fuzz-figures.tsv (the figures of spec/fuzzing.md)
# Each run starts from the seed corpus tests/fuzz/corpus/NAME with -seed=1; new inputs go to
# build/ci/tests/fuzz-scratch/NAME. A crash leaves crash-* (or leak-*, timeout-*, oom-*) in
# build/ci/findings/NAME: turn it into a named regression input and a test.
# The build is the test command's (tools/configure-ci.sh: build/ci), so one build serves both.
set -euo pipefail
cd "$(dirname "$0")/.."
usage="usage: tools/run-fuzz.sh NAME [SECONDS] | --all SECONDS"
all=false
if [ "${1:-}" = "--all" ]; then
  all=true
  seconds=${2:?$usage}
else
  name=${1:?$usage}
  seconds=${2:-300}
fi
bash tools/setup.sh --tests
bash tools/configure-ci.sh

# voice_structured_fuzz also starts from a real-size voice: the default voice (`fapcast say` builds
# it on first use, named by the key of the tables it was built from: the newest such file) when it
# exists, copied to build/ci/real-voice; inputs up to 32 MiB (libFuzzer cuts a longer seed to -max_len,
# and a cut voice no longer reads as a container: it would only be mutated as bytes).
default_voice=$(ls -t "${FAPCAST_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/fapcast}"/reference-seed1-*.fapv 2>/dev/null | head -n 1)

# run_one NAME: runs it for $seconds and prints "NAME<TAB>seconds<TAB>execs<TAB>cov<TAB>ft<TAB>corpus<TAB>findings".
run_one() {
  local target=$1 scratch=build/ci/tests/fuzz-scratch/$1 findings=build/ci/findings/$1 log rc=0
  local extra=()
  rm -rf "$findings"  # a finding counted is one of this run
  mkdir -p "$scratch" "$findings"
  if [ "$target" = voice_structured_fuzz ]; then
    extra=(-max_len=33554432 -rss_limit_mb=4096)
    if [ -f "$default_voice" ]; then
      mkdir -p build/ci/real-voice
      cp "$default_voice" build/ci/real-voice/
      extra+=(build/ci/real-voice)
    fi
  fi
  log=build/ci/findings/$target.log
  nice -n 19 "build/ci/tests/$target" -max_total_time="$seconds" -seed=1 -rss_limit_mb=2048 -timeout=10 \
    -print_final_stats=1 -artifact_prefix="$findings/" "${extra[@]:0:2}" "$scratch" "tests/fuzz/corpus/$target" \
    "${extra[@]:2}" >"$log" 2>&1 || rc=$?
  local execs cov ft corpus found
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  cov=$(grep -oE 'cov: [0-9]+' "$log" | tail -1 | cut -d' ' -f2 || true)
  ft=$(grep -oE 'ft: [0-9]+' "$log" | tail -1 | cut -d' ' -f2 || true)
  corpus=$(grep -oE 'corp: [0-9]+/[0-9]+[bKM]*' "$log" | tail -1 | cut -d' ' -f2 || true)
  found=$(find "$findings" -type f | wc -l)
  [ "$rc" = 0 ] || [ "$found" != 0 ] || found="exit $rc"
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$target" "$seconds" "${execs:-?}" "${cov:-?}" "${ft:-?}" "${corpus:-?}" "$found"
}

if ! $all; then
  cmake --build build/ci --target "$name"
  run_one "$name"
  exit 0
fi

cmake --build build/ci --target fapcast_fuzz_targets
out=build/ci/fuzz-figures.tsv
printf 'target\tseconds\texecutions\tcov\tft\tcorpus\tfindings\n' >"$out"
status=0
for src in tests/fuzz/*_fuzz.cpp; do
  target=$(basename "$src" .cpp)
  line=$(run_one "$target")
  printf '%s\n' "$line" | tee -a "$out"
  [ "$(printf '%s' "$line" | cut -f7)" = 0 ] || status=1
done
echo "figures: $out"
exit $status
