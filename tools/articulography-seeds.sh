#!/usr/bin/env bash
# How much does one voice's score on real articulography depend on the corpus draw? Records the
# SYNTHETIC reference corpus with each seed given (the default voice's recipe, another actor and
# other takes per seed), builds a voice from each, and runs `fapcast eval articulography` on
# MOCHA-TIMIT fsew0_001 (reference alignment and the own alignment) with each voice. Prints each
# voice's range ratio / r at zero lag / best lag per measure, then the mean, least and greatest
# over the seeds (spec/articulography.md, "One take, many voices"), and where r is lost: each
# phone's share of 1 - r (`--by-phone`), mean over the seeds.
#   tools/articulography-seeds.sh [SEED ...]        (default: 1 to 24; seed 1 is the default voice's)
#   FAPCAST=PATH   the executable (default build/release/cli/fapcast, what tools/build.sh makes)
#   WORK=DIR       where corpora (deleted after each build), voices and reports go
#                  (default build/articulography-seeds); voices are kept per executable (a
#                  folder named by its SHA-256) and reused by the same executable only
#   LABELS=FILE    the phone alignment to animate from (default fsew0_001.lab, MOCHA's own; an
#                  edited copy answers "what if this phone were labelled otherwise")
#   BASE=FILE      a copy of rows.tsv (in WORK) from an earlier run with other code or options: also prints,
#                  per measure, this run minus BASE seed by seed (the same seed records the same
#                  actor saying the same takes, so the corpus draw cancels): mean, its standard
#                  error, and in how many seeds it rose; and, when BASE's loss.tsv was kept beside
#                  it under the same name with "loss" for "rows", each phone's change of its
#                  share of 1 - r (where along the take r moved)
# Extra arguments for every `eval articulography` run: FAPCAST_EVAL_ARGS (e.g. "--jaw-weight 0.1").
set -euo pipefail
cd "$(dirname "$0")/.."
exe=${FAPCAST:-build/release/cli/fapcast}
work=${WORK:-build/articulography-seeds}
seeds=("$@")
# 24 voices: their means' standard error in r is about 0.02 and that of a paired difference about
# 0.01; six voices' means moved by 0.02-0.04 from the corpus draw alone.
[ ${#seeds[@]} -gt 0 ] || mapfile -t seeds < <(seq 1 24)
[ -x "$exe" ] || { echo "articulography-seeds: no executable $exe (bash tools/build.sh, or set FAPCAST)" >&2; exit 2; }
# Voices built by another executable may come from other code: one folder per executable.
voices=$work/$(sha256sum "$exe" | cut -c1-16)
mkdir -p "$voices"
m=tests/data/mocha/fsew0_001
labels=${LABELS:-$m.lab}
[ -f "$labels" ] || { echo "articulography-seeds: no label file $labels" >&2; exit 2; }
[ -z "${BASE:-}" ] || [ -f "$BASE" ] || { echo "articulography-seeds: no BASE file $BASE" >&2; exit 2; }

for seed in "${seeds[@]}"; do
  [[ $seed =~ ^[0-9]+$ ]] || { echo "articulography-seeds: seed '$seed' is not a whole number" >&2; exit 2; }
  voice=$voices/voice-seed$seed.fapv
  if [ ! -f "$voice" ]; then
    rm -rf "$work/corpus-seed$seed"
    "$exe" corpus record-reference -o "$work/corpus-seed$seed" --seed "$seed" -q >/dev/null
    "$exe" voice build "$work/corpus-seed$seed" -o "$voice" -q >/dev/null
    rm -rf "$work/corpus-seed$seed"
  fi
  # shellcheck disable=SC2086  # FAPCAST_EVAL_ARGS is a list of words
  "$exe" eval articulography $m.ema $m.wav "$labels" --text "This was easy for us." --voice "$voice" \
    --by-phone ${FAPCAST_EVAL_ARGS:-} -q > "$work/report-seed$seed.md" 2> "$work/report-seed$seed.log" ||
    { cat "$work/report-seed$seed.log" >&2; exit 1; }
done

# Table rows of the voice's two animations: "## animated from the reference alignment" / "... own
# alignment ..."; columns: measure, range real, range ours, ratio, r, best lag, r at best lag.
for seed in "${seeds[@]}"; do
  awk -v seed="$seed" -F' *\\| *' '
    /^## animated from the reference alignment/ { phones = "reference" }
    /^## animated from the own alignment/ { phones = "own" }
    /^## / && !/^## animated from the (reference|own) alignment/ { phones = "" }
    phones != "" && $2 ~ /^(lip aperture|jaw opening|lower-lip protrusion)$/ {
      lag = $7; sub(/ .*/, "", lag)
      printf "%s\t%s\t%s\t%s\t%s\t%s\n", seed, phones, $2, $5, $6, lag
    }' "$work/report-seed$seed.md"
done > "$work/rows.tsv"

# Each voice's "where r is lost" rows (--by-phone) of the reference alignment's animation: seed,
# row, phone, from s, to s, lips, jaw, protrusion (the same phones and spans for every voice).
for seed in "${seeds[@]}"; do
  awk -v seed="$seed" -F' *\\| *' '
    /^## / { phones = ($0 ~ /^## animated from the reference alignment/) }
    /^where r is lost/ { loss = phones; row = 0; next }
    loss && /^\| / && $2 != "phone" && $2 !~ /^-/ { printf "%s\t%d\t%s\t%s\t%s\t%s\t%s\t%s\n", seed, ++row, $2, $3, $4, $5, $6, $7 }
    /^$/ { loss = 0 }' "$work/report-seed$seed.md"
done > "$work/loss.tsv"

echo "fsew0_001 on voices of reference-corpus seeds ${seeds[*]} (ratio = range ours / real; r at zero lag; best lag ms, + = ours behind)"
echo
echo "| seed | alignment | lip ratio / r / lag | jaw ratio / r / lag | protrusion ratio / r / lag |"
echo "|---|---|---|---|---|"
awk -F'\t' '
  { key = $1 "\t" $2; if (!(key in seen)) { seen[key] = 1; order[++n] = key }
    cell[key, $3] = sprintf("%.2f / %.2f / %d", $4, $5, $6) }
  END { for (i = 1; i <= n; ++i) { split(order[i], k, "\t")
          printf "| %s | %s | %s | %s | %s |\n", k[1], k[2], cell[order[i], "lip aperture"],
                 cell[order[i], "jaw opening"], cell[order[i], "lower-lip protrusion"] } }' "$work/rows.tsv"
echo
echo "| alignment | measure | ratio mean (least-greatest) | r mean (least-greatest) | best lag ms mean (least-greatest) |"
echo "|---|---|---|---|---|"
awk -F'\t' '
  function keep(name, v) { sum[name] += v; if (!(name in lo) || v < lo[name]) lo[name] = v; if (!(name in hi) || v > hi[name]) hi[name] = v }
  { key = $2 "\t" $3; if (!(key in count)) order[++n] = key; ++count[key]
    keep(key "\tratio", $4); keep(key "\tr", $5); keep(key "\tlag", $6) }
  END { for (i = 1; i <= n; ++i) { key = order[i]; c = count[key]; split(key, k, "\t")
          printf "| %s | %s | %.2f (%.2f-%.2f) | %.2f (%.2f-%.2f) | %.0f (%d to %d) |\n", k[1], k[2],
                 sum[key "\tratio"] / c, lo[key "\tratio"], hi[key "\tratio"],
                 sum[key "\tr"] / c, lo[key "\tr"], hi[key "\tr"],
                 sum[key "\tlag"] / c, lo[key "\tlag"], hi[key "\tlag"] } }' "$work/rows.tsv"

echo
echo "where r is lost (reference alignment; per phone its share of 1 - r, mean over the voices; the"
echo "rows add up to the last, 1 - the mean r)"
echo
echo "| phone | from s | to s | lip aperture | jaw opening | lower-lip protrusion |"
echo "|---|---|---|---|---|---|"
awk -F'\t' '
  { if (!($2 in n)) { order[++rows] = $2; label[$2] = $3 "\t" $4 "\t" $5 }
    ++n[$2]; lips[$2] += $6; jaw[$2] += $7; prot[$2] += $8 }
  END { for (i = 1; i <= rows; ++i) { k = order[i]; split(label[k], l, "\t")
          printf "| %s | %s | %s | %.3f | %.3f | %.3f |\n", l[1], l[2], l[3], lips[k] / n[k], jaw[k] / n[k], prot[k] / n[k] } }' \
  "$work/loss.tsv"

[ -n "${BASE:-}" ] || exit 0
echo
echo "this run minus BASE ($BASE), seed by seed (seeds in both)"
echo
echo "| alignment | measure | r: mean difference (standard error), seeds up | ratio: mean difference | best lag ms: mean difference |"
echo "|---|---|---|---|---|"
awk -F'\t' '
  FNR == NR { base[$1 "\t" $2 "\t" $3] = $4 "\t" $5 "\t" $6; next }
  { key = $1 "\t" $2 "\t" $3; if (!(key in base)) next
    split(base[key], b, "\t"); m = $2 "\t" $3
    if (!(m in n)) order[++count] = m
    ++n[m]; d = $5 - b[2]; dr[m] += d; dr2[m] += d * d; if (d > 0) ++up[m]
    dratio[m] += $4 - b[1]; dlag[m] += $6 - b[3] }
  END { for (i = 1; i <= count; ++i) { m = order[i]; c = n[m]; split(m, k, "\t"); mean = dr[m] / c
          se = c > 1 ? sqrt((dr2[m] - c * mean * mean) / (c - 1) / c) : 0
          printf "| %s | %s | %+.3f (%.3f), %d of %d | %+.3f | %+.1f |\n", k[1], k[2], mean, se, up[m] + 0, c,
                 dratio[m] / c, dlag[m] / c } }' "$BASE" "$work/rows.tsv"

# The same per phone when BASE's loss.tsv was kept beside it under the same name with "loss" for
# "rows" (e.g. rows-before.tsv and loss-before.tsv): where along the take the change moved r.
base_loss=$(dirname "$BASE")/$(basename "$BASE" | sed 's/rows/loss/')
[ "$base_loss" != "$BASE" ] && [ -f "$base_loss" ] || exit 0
echo
echo "where r moved: per phone, this run's share of 1 - r minus BASE's ($base_loss), mean over the seeds"
echo "in both (negative = less lost here; a phone whose span is not in BASE, as with other LABELS, is left out)"
echo
echo "| phone | from s | to s | lip aperture | jaw opening | lower-lip protrusion |"
echo "|---|---|---|---|---|---|"
awk -F'\t' '
  FNR == NR { base[$1 "\t" $3 "\t" $4 "\t" $5] = $6 "\t" $7 "\t" $8; next }
  { key = $1 "\t" $3 "\t" $4 "\t" $5; if (!(key in base)) next
    split(base[key], b, "\t")
    if (!($2 in n)) { order[++rows] = $2; label[$2] = $3 "\t" $4 "\t" $5 }
    ++n[$2]; lips[$2] += $6 - b[1]; jaw[$2] += $7 - b[2]; prot[$2] += $8 - b[3] }
  END { for (i = 1; i <= rows; ++i) { k = order[i]; split(label[k], l, "\t")
          printf "| %s | %s | %s | %+.3f | %+.3f | %+.3f |\n", l[1], l[2], l[3], lips[k] / n[k], jaw[k] / n[k], prot[k] / n[k] } }' \
  "$base_loss" "$work/loss.tsv"
