#pragma once
// Cohen and Massaro's dominance function (1993): how strongly a phone's target pulls an
// articulatory channel at a given time from the phone's centre.
#include <cmath>

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

}  // namespace fapcast
