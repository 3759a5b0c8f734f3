#include "fba_plan.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cassert>
#include <limits>
#include <optional>

namespace fapcast::detail {
namespace {

constexpr std::int64_t kBit = 256;  // costs are in 1/256 bit
constexpr int kMarkersPerFlag = 18;  // markers before group positions 0, 4, 8, 12 of groups 2..10
constexpr int kFapcastIncrementLog2 = 3;
constexpr int kMaxCoefficient = 64;

std::int64_t ue_bits(std::uint64_t v) { return 2 * static_cast<std::int64_t>(std::bit_width(v + 1)) - 1; }
std::int64_t se_bits(std::int64_t v) { return ue_bits(v > 0 ? 2 * static_cast<std::uint64_t>(v) - 1 : 2 * static_cast<std::uint64_t>(-v)); }

// Bits of an alphabet [lo, hi] coding `symbols` adaptively (symbols outside: escaped, each about
// its bit length twice plus the escape symbol's share).
std::int64_t alphabet_cost(std::span<const std::int64_t> symbols, std::int64_t lo, std::int64_t hi, int increment,
                           std::int64_t enough) {
  const auto size = static_cast<std::size_t>(hi - lo + 1);
  std::vector<std::int32_t> counts(size + 1, 0);  // + the escape symbol
  std::int64_t total = static_cast<std::int64_t>(size) + 1, cost = 0;
  for (const std::int64_t s : symbols) {
    const bool escaped = s < lo || s > hi;
    const std::size_t i = escaped ? size : static_cast<std::size_t>(s - lo);
    cost += log2_q8(static_cast<std::uint64_t>(total)) - log2_q8(static_cast<std::uint64_t>(1 + increment * std::int64_t{counts[i]}));
    if (escaped) cost += kBit * (2 * std::bit_width(static_cast<std::uint64_t>(s < 0 ? -s : s)) + 2);
    ++counts[i];
    total += increment;
    if (cost > enough) break;
  }
  return cost;
}

// The alphabet for `symbols`: their extremes (0 included), narrowed around the median to at most
// kMaxDirectSymbols - 1 values when wider (the rest escaped).
std::pair<std::int32_t, std::int32_t> alphabet_for(std::span<const std::int64_t> symbols) {
  std::int64_t lo = 0, hi = 0;
  for (const std::int64_t s : symbols) {
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  }
  const std::int64_t width = hi - lo + 1;
  if (width <= kMaxDirectSymbols - 1) return {static_cast<std::int32_t>(lo), static_cast<std::int32_t>(hi)};
  std::vector<std::int64_t> sorted(symbols.begin(), symbols.end());
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
  const std::int64_t half = (kMaxDirectSymbols - 2) / 2;
  const std::int64_t median = sorted[sorted.size() / 2];
  const std::int64_t a = std::clamp<std::int64_t>(median - half, -(half * 2), 0);
  return {static_cast<std::int32_t>(a), static_cast<std::int32_t>(a + 2 * half)};
}

// Closed-loop P levels of FAP index i over frames (k, end) with `predictor`, from frames[k]'s
// intra reconstruction.
void predicted_run(std::span<const FapFrame> frames, std::size_t k, std::size_t end, std::size_t i, int step,
                   int predictor, std::vector<std::int64_t>& levels) {
  levels.clear();
  const auto first = static_cast<std::int32_t>(std::clamp<std::int64_t>(fba_quantise(frames[k].values[i], step) * step,
                                                                         std::numeric_limits<std::int32_t>::min(),
                                                                         std::numeric_limits<std::int32_t>::max()));
  std::int32_t r1 = first, r2 = first, r3 = first;
  for (std::size_t j = k + 1; j < end; ++j) {
    const std::int32_t p = fba_predict(predictor, r1, r2, r3);
    const std::int64_t level = fba_quantise(std::int64_t{frames[j].values[i]} - p, step);
    levels.push_back(level);
    r3 = r2;
    r2 = r1;
    r1 = static_cast<std::int32_t>(std::clamp<std::int64_t>(std::int64_t{p} + level * step,
                                                              std::numeric_limits<std::int32_t>::min(),
                                                              std::numeric_limits<std::int32_t>::max()));
  }
}

}  // namespace

std::int64_t log2_q8(std::uint64_t x) {
  const int e = std::bit_width(x) - 1;
  return std::int64_t{e} * 256 + static_cast<std::int64_t>(((x - (std::uint64_t{1} << e)) * 256) >> e);
}

std::int64_t adaptive_cost(std::span<const std::int32_t> symbols, std::int32_t offset, int size, int increment,
                           std::int64_t enough) {
  std::vector<std::int32_t> counts(static_cast<std::size_t>(size), 0);
  std::int64_t total = size, cost = 0;
  for (const std::int32_t s : symbols) {
    const auto i = static_cast<std::size_t>(s - offset);
    assert(i < counts.size());
    cost += log2_q8(static_cast<std::uint64_t>(total)) - log2_q8(static_cast<std::uint64_t>(1 + increment * std::int64_t{counts[i]}));
    ++counts[i];
    total += increment;
    if (cost > enough) break;
  }
  return cost;
}

StandardPlan plan_standard_period(std::span<const FapFrame> frames, std::size_t k, std::size_t nominal_end,
                                  const FbaCodingState& state, int q, bool resync_point) {
  StandardPlan plan;
  StandardIntraHeader& h = plan.header;
  h.fap_quant = q;
  const FapFrame& first = frames[k];
  const FapMask& mask = first.mask;
  // The ranges in force when the decoder reads the fields (the default rule first).
  std::array<FbaRangeLevels, kFapCount> base = state.ranges;
  if (base[3].i_min == 0 && base[3].i_max == 0) {
    for (int n = kFirstLowLevelFap; n <= kFapCount; ++n) base[fap_slot(n)] = fba_default_range_levels(n, q);
  }
  const FbaLevels intra = intra_levels(first, q);
  const auto ideal_intra = intra_range_fields(intra, mask, q);
  // P levels over the period, closed loop from the intra reconstruction (previous-value
  // prediction); the period ends before a level no field reaches.
  const int widest = fba_range_levels(kMaxRangeField, q);
  std::array<std::vector<std::int32_t>, kFapCount> plevels;
  FbaPrediction prediction;
  const FbaCodedFaps steps(mask, base, q);
  reconstruct(prediction, intra, steps, true);
  LevelExtremes extremes;
  std::size_t end = k + 1;
  for (; end < nominal_end; ++end) {
    const FbaLevels d = predicted_levels(prediction, steps, frames[end]);
    bool reachable = true;
    for (const FbaCodedFap& f : steps) reachable = reachable && d[f.index] >= -widest && d[f.index] <= widest;
    if (!reachable) break;
    for (const FbaCodedFap& f : steps) plevels[f.index].push_back(static_cast<std::int32_t>(d[f.index]));
    extremes.add(d);
    reconstruct(prediction, d, steps, false);
  }
  plan.end = end;
  std::array<FbaRangeFields, kFapCount> ideal = ideal_intra;
  const bool sized = size_predicted_fields(extremes, mask, q, ideal);
  assert(sized);
  (void)sized;
  const std::int64_t field_cost = kBit * (5 * steps.size() + kMarkersPerFlag);
  // The ends of a FAP's I range (p = false) or P range (p = true): sent (sized to the data) or in force.
  const auto ends = [&](const FbaCodedFap& f, bool p, bool send_max, bool send_min) {
    const FbaRangeFields& i = ideal[f.index];
    const FbaRangeLevels& b = base[f.index];
    const std::int32_t hi = send_max ? fba_range_levels(p ? i.p_max : i.i_max, q) : (p ? b.p_max : b.i_max);
    const std::int32_t lo = send_min ? -fba_range_levels(p ? i.p_min : i.i_min, q) : (p ? b.p_min : b.i_min);
    return std::pair{lo, hi};
  };
  // Keeping an end is possible where it covers the levels and, at a resync point, where it is the
  // default (what a decoder entering here holds).
  const auto keepable = [&](bool p, bool max_end) {
    if (!resync_point) return true;
    for (const FbaCodedFap& f : steps) {
      const FbaRangeLevels d = fba_default_range_levels(f.index + 1, q), b = base[f.index];
      if ((p ? (max_end ? b.p_max != d.p_max : b.p_min != d.p_min) : (max_end ? b.i_max != d.i_max : b.i_min != d.i_min)))
        return false;
    }
    return true;
  };
  // The cheapest of sending or keeping each end of the I (p = false) or P ranges. `symbols`: the
  // modelled bits of one FAP's symbols over [lo, hi] (or nullopt where they do not fit), stopping
  // past `enough`.
  const auto choose = [&](bool p, auto&& symbols, bool& send_max, bool& send_min) {
    std::int64_t best = std::numeric_limits<std::int64_t>::max();
    for (int combo = 0; combo < 4; ++combo) {
      const bool max_sent = combo & 1, min_sent = combo & 2;
      std::int64_t cost = (max_sent ? field_cost : 0) + (min_sent ? field_cost : 0);
      bool valid = (max_sent || keepable(p, true)) && (min_sent || keepable(p, false));
      for (int j = 0; j < steps.size() && valid && cost < best; ++j) {
        const auto [lo, hi] = ends(steps[j], p, max_sent, min_sent);
        const auto bits = hi - lo + 1 <= FrequencyModel::kMaxSymbols ? symbols(steps[j], lo, hi, best - cost)
                                                                      : std::optional<std::int64_t>{};
        valid = bits.has_value();
        cost += bits.value_or(0);
      }
      if (valid && cost < best) {
        best = cost;
        send_max = max_sent;
        send_min = min_sent;
      }
    }
  };
  // Intra: symbols are one-shot uniform, log2(size) each; P: the adaptive model over the range
  // coding the period's levels.
  choose(false,
         [&](const FbaCodedFap& f, std::int32_t lo, std::int32_t hi, std::int64_t) -> std::optional<std::int64_t> {
           if (intra[f.index] < lo || intra[f.index] > hi) return std::nullopt;
           return log2_q8(static_cast<std::uint64_t>(hi - lo + 1));
         },
         h.flags.i_max, h.flags.i_min);
  choose(true,
         [&](const FbaCodedFap& f, std::int32_t lo, std::int32_t hi, std::int64_t enough) -> std::optional<std::int64_t> {
           if (extremes.min[f.index] < lo || extremes.max[f.index] > hi) return std::nullopt;
           return adaptive_cost(plevels[f.index], lo, hi - lo + 1, 1, enough);
         },
         h.flags.p_max, h.flags.p_min);
  h.fields = ideal;
  return plan;
}

FapcastIntraHeader plan_fapcast_period(std::span<const FapFrame> frames, std::size_t k, std::size_t end, int q,
                                       bool choose) {
  FapcastIntraHeader h;
  h.fap_quant = q;
  h.log2_increment = kFapcastIncrementLog2;
  const int increment = 1 << kFapcastIncrementLog2;
  const FapMask& mask = frames[k].mask;
  std::vector<int> order;  // masked low-level FAPs, coded order
  for (int n = kFirstLowLevelFap; n <= kFapCount; ++n)
    if (mask.test(n)) order.push_back(n);
  std::array<std::vector<std::int64_t>, kFapCount> levels;  // the chosen predictor's levels
  std::vector<std::int64_t> trial;
  for (const int n : order) {
    const std::size_t i = fap_slot(n);
    const int step = fba_step(n, q);
    std::int64_t best = std::numeric_limits<std::int64_t>::max();
    for (int predictor = 0; predictor <= (choose ? kMaxPredictor : 0); ++predictor) {
      predicted_run(frames, k, end, i, step, predictor, trial);
      const auto [lo, hi] = alphabet_for(trial);
      const std::int64_t cost = alphabet_cost(trial, lo, hi, increment, best);
      if (cost < best) {
        best = cost;
        h.predictors[i] = static_cast<std::uint8_t>(predictor);
        levels[i] = trial;
      }
    }
  }
  // References: a FAP's level predicted from an earlier FAP's level in the same frame.
  std::array<std::vector<std::int64_t>, kFapCount> symbols = levels;
  for (std::size_t a = 0; a < order.size() && choose; ++a) {
    const std::size_t i = fap_slot(order[a]);
    const std::vector<std::int64_t>& e = levels[i];
    if (e.empty()) break;
    const auto [lo0, hi0] = alphabet_for(e);
    std::int64_t best = alphabet_cost(e, lo0, hi0, increment, std::numeric_limits<std::int64_t>::max()) + kBit;
    for (std::size_t b = 0; b < a; ++b) {
      const std::size_t m = fap_slot(order[b]);
      const std::vector<std::int64_t>& r = levels[m];
      double num = 0, den = 0;
      for (std::size_t j = 0; j < e.size(); ++j) {
        num += double(e[j]) * r[j];
        den += double(r[j]) * r[j];
      }
      if (den == 0) continue;
      const auto ls = static_cast<int>(std::lround(std::clamp(16 * num / den, -double(kMaxCoefficient), double(kMaxCoefficient))));
      for (const int c : {ls - 1, ls, ls + 1, 16}) {
        if (c == 0 || c < -kMaxCoefficient || c > kMaxCoefficient) continue;
        trial.resize(e.size());
        for (std::size_t j = 0; j < e.size(); ++j) trial[j] = e[j] - fba_reference_part(c, r[j]);
        const auto [lo, hi] = alphabet_for(trial);
        const std::int64_t cost = alphabet_cost(trial, lo, hi, increment, best) +
                                  kBit * (ue_bits(a - b) + se_bits(c));
        if (cost < best) {
          best = cost;
          h.reference[i] = static_cast<std::uint8_t>(order[b]);
          h.coefficient[i] = static_cast<std::int16_t>(c);
          symbols[i] = trial;
        }
      }
    }
  }
  for (const int n : order) {
    const std::size_t i = fap_slot(n);
    const auto [lo, hi] = alphabet_for(symbols[i]);
    h.p_min[i] = lo;
    h.p_max[i] = hi;
  }
  return h;
}

}  // namespace fapcast::detail
