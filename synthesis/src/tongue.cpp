#include "fapcast/synthesis/tongue.hpp"

#include "fapcast/math/dominance.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "fapcast/voice/voice_frame_grid.hpp"

namespace fapcast {
namespace {

// spec/tongue.tsv, row for row (the test checks it); rationale in spec/synthesis.md.
// phone, {shift_tip, raise_tip, thrust_tip, raise_body, roll}, {alpha_tip, alpha_body,
// theta_before, theta_after, c}.
struct Row {
  Phone phone;
  std::array<float, kTongueFapCount> value;
  std::array<float, 5> dominance;
};
constexpr std::array<Row, kPhoneCount> kRows{{
    {Phone::AA, {0, -40, -30, -150, 0}, {0.3f, 1.0f, 14.0f, 14.0f, 1.0f}},  // open back: tongue low and back
    {Phone::AE, {0, 40, 10, -60, 0}, {0.3f, 1.0f, 14.0f, 14.0f, 1.0f}},  // open front: low, tip behind lower teeth
    {Phone::AH, {0, 0, 0, 0, 0}, {0.3f, 1.0f, 14.0f, 14.0f, 1.0f}},  // central: near rest
    {Phone::AO, {0, -40, -40, -100, 0}, {0.3f, 1.0f, 14.0f, 14.0f, 1.0f}},  // open-mid back: low, retracted
    {Phone::AW, {0, -40, -20, -120, 0}, {0.3f, 1.0f, 14.0f, 14.0f, 1.0f}},  // nucleus a: low
    {Phone::AX, {0, 0, 0, 0, 0}, {0.3f, 0.5f, 14.0f, 14.0f, 1.0f}},  // schwa: central, near rest, weak (targetless)
    {Phone::AY, {0, -20, 0, -100, 0}, {0.3f, 1.0f, 14.0f, 14.0f, 1.0f}},  // nucleus a: low
    {Phone::EH, {0, 60, 10, 180, 0}, {0.3f, 1.0f, 14.0f, 14.0f, 1.0f}},  // mid front: body half raised
    {Phone::ER, {0, 250, -100, 250, 18000}, {0.8f, 1.0f, 16.0f, 16.0f, 1.0f}},  // r-coloured: tip up and back, cupped
    {Phone::EY, {0, 80, 10, 280, 0}, {0.3f, 1.0f, 14.0f, 14.0f, 1.0f}},  // close-mid front
    {Phone::IH, {0, 80, 10, 300, 0}, {0.3f, 1.0f, 14.0f, 14.0f, 1.0f}},  // near-close front
    {Phone::IY, {0, 100, 20, 420, 0}, {0.3f, 1.0f, 14.0f, 14.0f, 1.0f}},  // close front: body high under the palate
    {Phone::OW, {0, -20, -40, 120, 0}, {0.3f, 1.0f, 14.0f, 14.0f, 1.0f}},  // mid back
    {Phone::OY, {0, -20, -40, -60, 0}, {0.3f, 1.0f, 14.0f, 14.0f, 1.0f}},  // nucleus open-mid back
    {Phone::UH, {0, -20, -50, 260, 0}, {0.3f, 1.0f, 14.0f, 14.0f, 1.0f}},  // near-close back
    {Phone::UW, {0, -20, -60, 380, 0}, {0.3f, 1.0f, 14.0f, 14.0f, 1.0f}},  // close back: dorsum high, tip low
    {Phone::B, {0, 0, 0, 60, 0}, {0.2f, 0.2f, 20.0f, 20.0f, 1.0f}},  // lips only: tongue free (from context)
    {Phone::CH, {0, 380, -60, 250, 10000}, {1.0f, 0.8f, 18.0f, 18.0f, 1.0f}},  // postalveolar: blade up behind the ridge, grooved
    {Phone::D, {0, 550, 20, 80, 0}, {1.0f, 0.6f, 18.0f, 18.0f, 1.0f}},  // alveolar: tip on the ridge
    {Phone::DH, {0, 230, 120, 40, 0}, {1.0f, 0.6f, 18.0f, 18.0f, 1.0f}},  // dental: tip forward between the teeth
    {Phone::F, {0, 0, 0, 60, 0}, {0.2f, 0.2f, 20.0f, 20.0f, 1.0f}},  // lips only
    {Phone::G, {0, -30, -40, 500, 0}, {0.4f, 1.0f, 18.0f, 18.0f, 1.0f}},  // velar: dorsum against the soft palate
    {Phone::HH, {0, 0, 0, 60, 0}, {0.1f, 0.1f, 20.0f, 20.0f, 1.0f}},  // glottal: tongue from context
    {Phone::JH, {0, 380, -60, 250, 10000}, {1.0f, 0.8f, 18.0f, 18.0f, 1.0f}},  // as CH
    {Phone::K, {0, -30, -40, 500, 0}, {0.4f, 1.0f, 18.0f, 18.0f, 1.0f}},  // velar
    {Phone::L, {0, 520, 0, -40, 0}, {1.0f, 0.6f, 18.0f, 18.0f, 1.0f}},  // lateral: tip up, sides down
    {Phone::M, {0, 0, 0, 60, 0}, {0.2f, 0.2f, 20.0f, 20.0f, 1.0f}},  // lips only
    {Phone::N, {0, 550, 20, 80, 0}, {1.0f, 0.6f, 18.0f, 18.0f, 1.0f}},  // alveolar
    {Phone::NG, {0, -30, -40, 500, 0}, {0.4f, 1.0f, 18.0f, 18.0f, 1.0f}},  // velar
    {Phone::P, {0, 0, 0, 60, 0}, {0.2f, 0.2f, 20.0f, 20.0f, 1.0f}},  // lips only
    {Phone::R, {0, 250, -100, 250, 18000}, {0.8f, 1.0f, 16.0f, 16.0f, 1.0f}},  // bunched r: tip up and back, cupped
    {Phone::S, {0, 420, 20, 200, 15000}, {1.0f, 0.6f, 18.0f, 18.0f, 1.0f}},  // sibilant: tip near the ridge, grooved
    {Phone::SH, {0, 380, -60, 250, 10000}, {1.0f, 0.8f, 18.0f, 18.0f, 1.0f}},  // postalveolar
    {Phone::T, {0, 550, 20, 80, 0}, {1.0f, 0.6f, 18.0f, 18.0f, 1.0f}},  // alveolar
    {Phone::TH, {0, 230, 120, 40, 0}, {1.0f, 0.6f, 18.0f, 18.0f, 1.0f}},  // dental
    {Phone::V, {0, 0, 0, 60, 0}, {0.2f, 0.2f, 20.0f, 20.0f, 1.0f}},  // lips only
    {Phone::W, {0, -20, -50, 350, 0}, {0.3f, 0.8f, 16.0f, 16.0f, 1.0f}},  // labial-velar: dorsum raised back
    {Phone::Y, {0, 100, 20, 450, 0}, {0.4f, 1.0f, 16.0f, 16.0f, 1.0f}},  // palatal: body high front
    {Phone::Z, {0, 420, 20, 200, 15000}, {1.0f, 0.6f, 18.0f, 18.0f, 1.0f}},  // sibilant
    {Phone::ZH, {0, 380, -60, 250, 10000}, {1.0f, 0.8f, 18.0f, 18.0f, 1.0f}},  // postalveolar
    {Phone::SIL, {0, 0, 0, 0, 0}, {0.5f, 0.5f, 20.0f, 20.0f, 1.0f}},  // rest
}};

constexpr std::array<TongueTarget, kPhoneCount> make_table() {
  std::array<TongueTarget, kPhoneCount> out{};
  for (std::size_t i = 0; i < kPhoneCount; ++i) {
    const Row& r = kRows[i];
    out[i] = {r.phone, r.value, r.dominance[0], r.dominance[1], r.dominance[2], r.dominance[3],
              r.dominance[4]};
  }
  return out;
}
constexpr auto kTable = make_table();

constexpr bool in_phone_order() {
  for (std::size_t i = 0; i < kPhoneCount; ++i)
    if (static_cast<std::size_t>(kTable[i].phone) != i) return false;
  return true;
}
static_assert(in_phone_order(), "tongue table rows must follow Phone order");

// A frame n sees a phone of frames [f, e) at tau = n / 60 - (f + e) / 120 s = m / 120 s, m = 2n - f - e
// an integer: the tip's decay exp(-theta |tau|^c) tabled over m for every decay shape of the table
// (four distinct ones), up to the reach (|m| <= 48; a phone's own far frames are computed).
constexpr std::int64_t kHalfFramesPerSecond = 2 * kVoiceFramesPerSecond;
constexpr auto kReachHalfFrames = static_cast<std::int64_t>(kTongueReachS * kHalfFramesPerSecond + 0.5);

double decay_at(const TongueTarget& p, std::int64_t m) {
  return p.tip().falloff(static_cast<double>(m) / static_cast<double>(kHalfFramesPerSecond));
}

class DecayTable {
 public:
  DecayTable() {
    for (std::size_t i = 0; i < kPhoneCount; ++i) {
      const TongueTarget& p = kTable[i];
      std::size_t same = 0;
      while (same < i && !same_decay(kTable[same], p)) ++same;
      if (same < i) {
        row_of_[i] = row_of_[same];
        continue;
      }
      row_of_[i] = rows_.size();
      auto& row = rows_.emplace_back();
      for (std::int64_t m = -kReachHalfFrames; m <= kReachHalfFrames; ++m)
        row[static_cast<std::size_t>(m + kReachHalfFrames)] = decay_at(p, m);
    }
  }
  // Phone p's row, at its centre: row[m] is the decay m half frames away, |m| <= kReachHalfFrames.
  const double* centre_of(const TongueTarget& p) const {
    return rows_[row_of_[static_cast<std::size_t>(p.phone)]].data() + kReachHalfFrames;
  }

 private:
  static bool same_decay(const TongueTarget& a, const TongueTarget& b) {
    return a.theta_before_per_s == b.theta_before_per_s && a.theta_after_per_s == b.theta_after_per_s && a.c == b.c;
  }
  std::vector<std::array<double, 2 * kReachHalfFrames + 1>> rows_;
  std::array<std::size_t, kPhoneCount> row_of_{};
};

const DecayTable& decay_table() {
  static const DecayTable table;
  return table;
}

}  // namespace

std::span<const TongueTarget, kPhoneCount> tongue_table() { return kTable; }

const TongueTarget& tongue_target(Phone phone) { return kTable[static_cast<std::size_t>(phone)]; }

Eigen::MatrixXf tongue_track(std::span<const TargetPhone> targets, std::span<const Phone> phones) {
  if (targets.size() != phones.size())
    throw std::invalid_argument("tongue: " + std::to_string(targets.size()) + " targets but " +
                                std::to_string(phones.size()) + " phones");
  const std::int64_t frames = targets.empty() ? 0 : targets.back().end_frame;
  Eigen::MatrixXf out = Eigen::MatrixXf::Zero(static_cast<Eigen::Index>(frames), kTongueFapCount);
  if (targets.empty()) return out;
  constexpr double kFps = static_cast<double>(kVoiceFramesPerSecond);
  // Each phone's centre and row, looked up once.
  struct Source {
    double centre_s;
    std::int64_t centre_half_frames;  // f + e: twice the centre, in frames
    const TongueTarget* target;
    const double* decay;                          // DecayTable::centre_of(*target)
    double alpha_tip, alpha_body;                 // the row's, widened once
    std::array<double, kTongueFapCount> value;
    // The tip's decay at frame n (tip and body share it, spec/tongue.tsv).
    double decay_at_frame(std::int64_t n) const {
      const std::int64_t m = 2 * n - centre_half_frames;
      return m >= -kReachHalfFrames && m <= kReachHalfFrames ? decay[m] : decay_at(*target, m);
    }
  };
  const DecayTable& decay = decay_table();
  std::vector<Source> sources(targets.size());
  for (std::size_t s = 0; s < targets.size(); ++s) {
    const std::int64_t twice = targets[s].first_frame + targets[s].end_frame;
    const TongueTarget& p = tongue_target(phones[s]);
    Source& source = sources[s];
    source = {0.5 * static_cast<double>(twice) / kFps, twice, &p, decay.centre_of(p), p.alpha_tip, p.alpha_body, {}};
    for (std::size_t f = 0; f < kTongueFapCount; ++f) source.value[f] = p.fap_value[f];
  }

  float* column[kTongueFapCount];
  for (std::size_t f = 0; f < kTongueFapCount; ++f) column[f] = out.col(static_cast<Eigen::Index>(f)).data();
  DominanceBlend blend(kTongueFapCount);
  std::size_t here = 0;  // the target phone that owns frame n
  for (std::int64_t n = targets.front().first_frame; n < frames; ++n) {
    while (n >= targets[here].end_frame) ++here;
    const double t = static_cast<double>(n) / kFps;
    blend.clear();
    auto add = [&](const Source& p) {  // FAPs 43-45 take the tip's dominance, 46-47 the body's
      const double fall = p.decay_at_frame(n);
      const double tip = p.alpha_tip * fall, body = p.alpha_body * fall;
      for (std::size_t f = 0; f < 3; ++f) blend.add(f, tip, p.value[f]);
      for (std::size_t f = 3; f < kTongueFapCount; ++f) blend.add(f, body, p.value[f]);
    };
    add(sources[here]);  // always: a long phone's own frames far from its centre still have a value
    for (std::size_t s = here; s-- > 0 && t - sources[s].centre_s <= kTongueReachS;) add(sources[s]);
    for (std::size_t s = here + 1; s < targets.size() && sources[s].centre_s - t <= kTongueReachS; ++s)
      add(sources[s]);
    for (std::size_t f = 0; f < kTongueFapCount; ++f) column[f][n] = static_cast<float>(blend.value(f));
  }
  return out;
}

}  // namespace fapcast
