#pragma once
// Cohen and Massaro's coarticulation (1993): a dominance function per phone and channel, and the
// blend of the phones' targets by their dominances. The reference talker's articulation, the
// tongue of synthesis and the dominance baseline of the evaluation all blend with these.
#include <cmath>
#include <cstddef>
#include <vector>

namespace fapcast {

// D(tau) = alpha * exp(-theta * |tau|^c): theta_before for tau < 0, theta_after for tau >= 0.
struct Dominance {
  float alpha;               // > 0, peak dominance at the phone centre
  float theta_before_per_s;  // rate of decay before the centre (anticipation), 1/s^c
  float theta_after_per_s;   // rate of decay after the centre (carry-over), 1/s^c
  float c;                   // shape exponent, > 0 (1: exponential; 2: plateau then fall)
  // Dominance at tau seconds from the phone centre: alpha * falloff(tau_s).
  double at(double tau_s) const { return alpha * falloff(tau_s); }
  // exp(-theta * |tau|^c), the part that does not depend on alpha (shared by dominances that
  // differ only in alpha, such as the tongue's tip and body). Inline: the tongue and the talker
  // evaluate it for every phone near every frame.
  double falloff(double tau_s) const {
    const double theta = tau_s < 0 ? theta_before_per_s : theta_after_per_s;
    // c = 1 (every row today) skips std::pow, the most expensive step of a blend; same value.
    const double x = c == 1.0f ? std::abs(tau_s) : std::pow(std::abs(tau_s), static_cast<double>(c));
    return std::exp(-theta * x);
  }
};

// The blend at one instant: per channel the dominance-weighted mean of the targets,
// F = sum_s D_s T_s / sum_s D_s, summed in double in the order the phones are added; 0 in a
// channel no phone dominates (sum D = 0). Reused frame after frame: clear(), add() the phones
// near the frame, read value().
class DominanceBlend {
 public:
  explicit DominanceBlend(std::size_t channels) : numerator_(channels, 0.0), denominator_(channels, 0.0) {}

  std::size_t channels() const { return numerator_.size(); }
  void clear() {
    for (std::size_t c = 0; c < numerator_.size(); ++c) numerator_[c] = denominator_[c] = 0.0;
  }
  // One phone's pull on `channel`: its dominance there (>= 0) and its target.
  void add(std::size_t channel, double dominance, double target) {
    numerator_[channel] += dominance * target;
    denominator_[channel] += dominance;
  }
  double value(std::size_t channel) const {
    return denominator_[channel] > 0 ? numerator_[channel] / denominator_[channel] : 0.0;
  }

 private:
  std::vector<double> numerator_, denominator_;
};

}  // namespace fapcast
