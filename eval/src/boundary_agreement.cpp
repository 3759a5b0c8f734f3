#include "fapcast/eval/boundary_agreement.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include "fapcast/phonetics/viseme.hpp"

namespace fapcast {

namespace {

std::vector<TimedPhone> merged(std::span<const TimedPhone> phones) {
  std::vector<TimedPhone> out;
  for (const TimedPhone& p : phones) {
    if (p.end_sample <= p.start_sample) continue;
    if (!out.empty() && out.back().phone == p.phone) {
      out.back().end_sample = p.end_sample;
      continue;
    }
    out.push_back(p);
  }
  return out;
}

// Edit costs in half units: equal 0, same search class 1, other phone 2, insertion or deletion 2.
int substitution_cost(Phone a, Phone b) {
  if (a == b) return 0;
  return search_viseme(a) == search_viseme(b) ? 1 : 2;
}
constexpr int kGapCost = 2;

}  // namespace

double BoundaryAgreement::within(double tolerance_s) const {
  if (errors_s.empty()) return 0;
  const auto n = std::count_if(errors_s.begin(), errors_s.end(), [&](double e) { return e <= tolerance_s; });
  return static_cast<double>(n) / static_cast<double>(errors_s.size());
}

BoundaryAgreement boundary_agreement(std::span<const TimedPhone> reference, std::span<const TimedPhone> hypothesis,
                                     SampleRate sample_rate) {
  if (!sample_rate.valid()) throw std::invalid_argument("boundary_agreement: no sample rate");
  const std::vector<TimedPhone> ref = merged(reference), hyp = merged(hypothesis);
  BoundaryAgreement out;
  out.reference_phones = ref.size();
  const std::size_t n = ref.size(), m = hyp.size();
  // cost[i][j]: ref[0, i) against hyp[0, j)
  std::vector<int> cost((n + 1) * (m + 1));
  auto at = [&](std::size_t i, std::size_t j) -> int& { return cost[i * (m + 1) + j]; };
  for (std::size_t i = 0; i <= n; ++i) at(i, 0) = static_cast<int>(i) * kGapCost;
  for (std::size_t j = 0; j <= m; ++j) at(0, j) = static_cast<int>(j) * kGapCost;
  for (std::size_t i = 1; i <= n; ++i)
    for (std::size_t j = 1; j <= m; ++j)
      at(i, j) = std::min({at(i - 1, j - 1) + substitution_cost(ref[i - 1].phone, hyp[j - 1].phone),
                           at(i - 1, j) + kGapCost, at(i, j - 1) + kGapCost});
  // partner[i]: the hypothesis phone paired with ref[i], or -1
  std::vector<std::ptrdiff_t> partner(n, -1);
  for (std::size_t i = n, j = m; i > 0 || j > 0;) {
    if (i > 0 && j > 0 && at(i, j) == at(i - 1, j - 1) + substitution_cost(ref[i - 1].phone, hyp[j - 1].phone)) {
      partner[i - 1] = static_cast<std::ptrdiff_t>(j - 1);
      --i, --j;
    } else if (i > 0 && at(i, j) == at(i - 1, j) + kGapCost) {
      --i;
    } else {
      --j;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (partner[i] < 0) ++out.deleted;
    else if (hyp[static_cast<std::size_t>(partner[i])].phone == ref[i].phone) ++out.matched;
    else ++out.substituted;
  }
  const double rate = static_cast<double>(sample_rate.hz);
  for (std::size_t i = 1; i < n; ++i) {
    // hypothesis boundaries between the partners of the nearest paired phones either side
    std::ptrdiff_t before = -1, after = static_cast<std::ptrdiff_t>(m);
    for (std::size_t k = i; k-- > 0;)
      if (partner[k] >= 0) { before = partner[k]; break; }
    for (std::size_t k = i; k < n; ++k)
      if (partner[k] >= 0) { after = partner[k]; break; }
    const std::ptrdiff_t lo = std::max<std::ptrdiff_t>(before + 1, 1);
    const std::ptrdiff_t hi = std::min<std::ptrdiff_t>(std::max(after, lo), static_cast<std::ptrdiff_t>(m) - 1);
    double best = std::numeric_limits<double>::infinity();
    for (std::ptrdiff_t j = lo; j <= hi; ++j)
      best = std::min(best, std::abs(static_cast<double>(hyp[static_cast<std::size_t>(j)].start_sample - ref[i].start_sample)));
    if (m < 2) best = static_cast<double>(std::max(ref[i].start_sample, ref.back().end_sample - ref[i].start_sample));
    out.errors_s.push_back(best / rate);
  }
  return out;
}

}  // namespace fapcast
