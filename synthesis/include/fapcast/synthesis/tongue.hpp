#pragma once
// The parametric tongue (paper section 3.4: the tongue is not captured; a model driven by the
// phones moves it): per phone a target for MPEG-4 FAPs 43-47 and Cohen-Massaro dominances
// (spec/tongue.tsv), blended over the phone timeline like the reference talker's channels
// (coarticulation.hpp), so /t d n l/ lift the tip, /th dh/ push it between the teeth, /k g ng/
// raise the back and open vowels lower it, with anticipation and carry-over between phones.
#include "fapcast/math/dominance.hpp"
#include "fapcast/phonetics/phone.hpp"
#include "fapcast/synthesis/unit_concatenation.hpp"

#include <Eigen/Core>

#include <array>
#include <span>

namespace fapcast {

// FAPs 43..47: shift_tongue_tip, raise_tongue_tip, thrust_tongue_tip, raise_tongue, tongue_roll.
inline constexpr int kFirstTongueFap = 43;
inline constexpr std::size_t kTongueFapCount = 5;

struct TongueTarget {
  Phone phone;
  // In each FAP's own unit (MW/1024 for 43 and 45, MNS/1024 for 44 and 46, AU for 47),
  // relative to the tongue at rest: face-relative, so one table serves every face.
  std::array<float, kTongueFapCount> fap_value;
  // Dominance of the tip (FAPs 43-45; alpha = alpha_tip) and of the body (46-47).
  float alpha_tip, alpha_body, theta_before_per_s, theta_after_per_s, c;
  Dominance tip() const { return {alpha_tip, theta_before_per_s, theta_after_per_s, c}; }
  Dominance body() const { return {alpha_body, theta_before_per_s, theta_after_per_s, c}; }
};

// One row per phone, in Phone order (spec/tongue.tsv, which a test compares).
std::span<const TongueTarget, kPhoneCount> tongue_table();

// A phone's target row.
const TongueTarget& tongue_target(Phone phone);

// Tongue FAP values per voice frame: frames x 5 (columns FAP 43..47), same units as the table.
// Phones are the target phones on the 60 fps grid with their phones; each contributes at frame
// n (time n / 60 s) with its dominance around its centre. Phones whose centre lies more than
// kTongueReachS away are skipped (their weight is below 0.4 % of their peak): O(frames), not
// O(frames x phones). Throws std::invalid_argument when the spans differ in length.
inline constexpr double kTongueReachS = 0.4;
Eigen::MatrixXf tongue_track(std::span<const TargetPhone> targets, std::span<const Phone> phones);

}  // namespace fapcast
