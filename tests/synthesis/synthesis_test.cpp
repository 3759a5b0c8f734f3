// Synthesis from timed phones: the 60 fps grid (exact, agrees with the codec, no drift), the
// input rules, viseme fallbacks, the parametric tongue and the whole synthesize() on SYNTHETIC
// graphs whose class shapes are known.
#include "fapcast/synthesis/synthesis.hpp"
#include "fapcast/synthesis/tongue.hpp"
#include "fapcast/core/input_error.hpp"
#include "fapcast/core/tsv_table.hpp"
#include "fapcast/core/frame_rate.hpp"
#include "support/synthetic_voice_graph.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>

namespace fapcast {
namespace {

constexpr std::int64_t kRate = 22050;
constexpr SampleRate kSampleRate{kRate};

// Consecutive phones of `ms` milliseconds each from sample 0.
std::vector<TimedPhone> phones(const std::vector<std::pair<Phone, int>>& spec, std::int64_t rate = kRate) {
  std::vector<TimedPhone> out;
  std::int64_t at = 0;
  for (const auto& [p, ms] : spec) {
    const std::int64_t end = at + ms * rate / 1000;
    out.push_back({p, at, end});
    at = end;
  }
  return out;
}

std::string rule_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.rule();
  }
  return "";
}

TEST(VoiceFrameGrid, NoDriftOverAnHour) {
  const std::int64_t hour = 3600 * kVoiceFramesPerSecond;
  EXPECT_EQ(frame_to_sample(hour, kVoiceFrameRate, SampleRate{22050}), 3600 * 22050);
  EXPECT_EQ(frame_to_sample(hour, kVoiceFrameRate, SampleRate{44100}), 3600 * 44100);
  EXPECT_EQ(first_frame_at(3600 * 22050, kVoiceFrameRate, SampleRate{22050}), hour);
  // 22050 / 60 = 367.5 samples per frame: odd frames round up, never accumulate.
  EXPECT_EQ(frame_to_sample(hour + 1, kVoiceFrameRate, SampleRate{22050}), 3600 * 22050 + 368);
  EXPECT_EQ(frame_to_sample(10 * hour + 3, kVoiceFrameRate, SampleRate{22050}), 36000 * 22050 + 1103);
}

TEST(PlaceOnVoiceGrid, ContiguousFromFrameZeroWithHolds) {
  const auto p = phones({{Phone::SIL, 100}, {Phone::M, 80}, {Phone::AA, 150}, {Phone::F, 90}, {Phone::SIL, 100}});
  const TargetTimeline t = place_on_voice_grid(p, kSampleRate);
  ASSERT_EQ(t.phones.size(), 5u);
  EXPECT_EQ(t.phones.front().first_frame, 0);
  for (std::size_t i = 1; i < t.phones.size(); ++i) EXPECT_EQ(t.phones[i].first_frame, t.phones[i - 1].end_frame);
  EXPECT_EQ(t.frame_count(), first_frame_at(p.back().end_sample, kVoiceFrameRate, SampleRate{kRate}));
  EXPECT_TRUE(t.phones[1].hold);   // m
  EXPECT_FALSE(t.phones[2].hold);  // aa
  EXPECT_TRUE(t.phones[3].hold);   // f
  EXPECT_EQ(t.phones[1].viseme, VisemeClass::kBilabial);
  EXPECT_EQ(t.dropped, 0u);
  EXPECT_EQ(t.gaps_filled, 0u);
}

TEST(PlaceOnVoiceGrid, GapsBecomeSilenceAndTheAudioTailToo) {
  std::vector<TimedPhone> p{{Phone::AA, 2205, 4410}, {Phone::T, 6615, 8820}};
  const TargetTimeline t = place_on_voice_grid(p, kSampleRate, 22050);
  ASSERT_EQ(t.phones.size(), 5u);  // sil aa sil t sil
  EXPECT_EQ(t.phone_of[0], Phone::SIL);
  EXPECT_EQ(t.phone_of[2], Phone::SIL);
  EXPECT_EQ(t.phone_of[4], Phone::SIL);
  EXPECT_EQ(t.gaps_filled, 3u);
  EXPECT_EQ(t.frame_count(), 60);
  EXPECT_EQ(t.phones[1].first_frame, 6);
}

TEST(PlaceOnVoiceGrid, ZeroAndSubFrameDurationsAreDropped) {
  // Frame instants at 22050 Hz: 6 -> 2205, 7 -> 2573 (367.5 samples apart).
  std::vector<TimedPhone> p{{Phone::AA, 0, 2206},
                            {Phone::T, 2206, 2206},   // zero
                            {Phone::D, 2206, 2500},   // 13 ms, no frame instant
                            {Phone::IY, 2500, 4410}};
  const TargetTimeline t = place_on_voice_grid(p, kSampleRate);
  ASSERT_EQ(t.phones.size(), 2u);
  EXPECT_EQ(t.dropped, 2u);
  EXPECT_EQ(t.phones[1].first_frame, t.phones[0].end_frame);
  EXPECT_EQ(t.frame_count(), 12);
}

TEST(PlaceOnVoiceGrid, RefusesReversedOverlappingAndNegativePhones) {
  using P = std::vector<TimedPhone>;
  EXPECT_EQ(rule_of([] { place_on_voice_grid(P{{Phone::AA, 100, 50}}, kSampleRate); }), "phone-reversed");
  EXPECT_EQ(rule_of([] { place_on_voice_grid(P{{Phone::AA, -5, 50}}, kSampleRate); }), "phone-negative-start");
  EXPECT_EQ(rule_of([] {
              place_on_voice_grid(P{{Phone::AA, 0, 500}, {Phone::T, 400, 900}}, kSampleRate);
            }), "phone-overlap");
  try {
    place_on_voice_grid(P{{Phone::AA, 0, 500}, {Phone::T, 400, 900}}, kSampleRate, 0, "x.lab");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("x.lab"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("phone 1 'T'"), std::string::npos) << e.what();
  }
  // A piece of a longer text (say's pieces): the index counts from the text's start.
  try {
    place_on_voice_grid(P{{Phone::AA, 0, 500}, {Phone::T, 400, 900}}, kSampleRate, 0, "say: text", 120);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("phone 121 'T'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(place_on_voice_grid(P{}, SampleRate{0}), std::invalid_argument);
}

TEST(CoveredViseme, FallsBackToTheNearestRecordedShape) {
  using V = VisemeClass;
  // A voice without laterals or dentals: /l/ borrows alveolar units, /th/ too.
  const auto g = test::synthetic_voice_graph(4, 10, 3, 2, 1, 0.0f, {V::kAlveolar, V::kSilence, V::kOpenUnrounded});
  EXPECT_EQ(covered_viseme(*g.graph, V::kAlveolar), V::kAlveolar);
  EXPECT_EQ(covered_viseme(*g.graph, V::kLateral), V::kAlveolar);
  EXPECT_EQ(covered_viseme(*g.graph, V::kDental), V::kAlveolar);
  EXPECT_EQ(covered_viseme(*g.graph, V::kOpenMidRounded), V::kOpenUnrounded);  // after mid_rounded
  EXPECT_EQ(rule_of([&] { covered_viseme(*g.graph, V::kCloseRounded); }), "viseme-not-covered");
  for (std::size_t v = 0; v < kVisemeClassCount; ++v)
    for (VisemeClass s : viseme_fallbacks()[v].substitutes) EXPECT_NE(static_cast<std::size_t>(s), v);
}

TEST(Synthesize, ReachesTheTargetShapesAndKeepsClosures) {
  const auto g = test::synthetic_voice_graph(200, 20, 6, 3, 5, 0.02f);
  const auto p = phones({{Phone::SIL, 200}, {Phone::B, 90}, {Phone::AA, 160}, {Phone::T, 70},
                         {Phone::IY, 140}, {Phone::M, 100}, {Phone::UW, 150}, {Phone::SIL, 200}});
  SynthesisOptions options;
  options.search.beta = 0.1;
  options.search.max_active = 32;
  const SynthesizedTrack s = synthesize(*g.graph, g.frames, p, kSampleRate, 0, options);
  const auto& t = s.timeline.phones;
  ASSERT_EQ(s.pca_frames.rows(), s.timeline.frame_count());
  ASSERT_EQ(s.pca_frames.cols(), 3);
  ASSERT_EQ(s.tongue.rows(), s.pca_frames.rows());
  ASSERT_EQ(s.search.states.size(), t.size());
  EXPECT_EQ(s.substituted, 0u);
  for (std::size_t i = 0; i < t.size(); ++i) {
    const auto mid = (t[i].first_frame + t[i].end_frame) / 2;
    const float want = test::class_shape(t[i].viseme, 0);
    EXPECT_NEAR(s.pca_frames(mid, 0), want, t[i].hold ? 0.1f : 0.35f) << "phone " << i;
  }
  // The bilabials close: their middle frames reach the closure value (-1) despite smoothing.
  for (std::size_t i : {1u, 5u}) {
    const auto mid = (t[i].first_frame + t[i].end_frame) / 2;
    EXPECT_LT(s.pca_frames(mid, 0), -0.9f) << "phone " << i;
  }
  EXPECT_FALSE(s.search.stats.active_per_step.empty());
  // The cap from the second phone on (the first keeps every state of its class: spec/search.md).
  for (std::size_t n = 1; n < s.search.stats.active_per_step.size(); ++n) EXPECT_LE(s.search.stats.active_per_step[n], 32u);
}

TEST(Synthesize, SubstitutesMissingClassesAndCountsThem) {
  using V = VisemeClass;
  const auto g = test::synthetic_voice_graph(20, 10, 4, 2, 9, 0.0f, {V::kSilence, V::kAlveolar, V::kOpenUnrounded});
  const auto p = phones({{Phone::SIL, 100}, {Phone::L, 100}, {Phone::AA, 100}, {Phone::SIL, 100}});
  const SynthesizedTrack s = synthesize(*g.graph, g.frames, p, kSampleRate);
  EXPECT_EQ(s.substituted, 1u);
  EXPECT_EQ(s.timeline.phones[1].viseme, V::kLateral) << "the timeline keeps the phone asked for";
  const auto mid = (s.timeline.phones[1].first_frame + s.timeline.phones[1].end_frame) / 2;
  EXPECT_NEAR(s.pca_frames(mid, 0), test::class_shape(V::kAlveolar, 0), 0.2f);
}

TEST(Synthesize, EmptyPhonesGiveAnEmptyTrackAndBadPhonesAnError) {
  const auto g = test::synthetic_voice_graph(5, 10, 4, 2, 3);
  const SynthesizedTrack s = synthesize(*g.graph, g.frames, {}, kSampleRate);
  EXPECT_EQ(s.pca_frames.rows(), 0);
  EXPECT_EQ(s.tongue.rows(), 0);
  std::vector<TimedPhone> bad{{Phone::AA, 10, 5}};
  EXPECT_THROW(synthesize(*g.graph, g.frames, bad, kSampleRate), InputError);
}

TEST(Tongue, TableMatchesSpec) {
  const std::filesystem::path file = std::filesystem::path(FAPCAST_SOURCE_DIR) / "spec" / "tongue.tsv";
  const auto rows = read_tsv(file, 11);
  ASSERT_EQ(rows.size(), kPhoneCount);
  for (std::size_t i = 0; i < kPhoneCount; ++i) {
    const TongueTarget& t = tongue_table()[i];
    const std::string want = t.phone == Phone::SIL ? "sil" : std::string(arpabet(t.phone));
    EXPECT_EQ(rows[i].fields[0], want);
    for (std::size_t f = 0; f < kTongueFapCount; ++f)
      EXPECT_EQ(tsv_float(file, rows[i], f + 1), t.fap_value[f]) << want << " column " << f + 1;
    EXPECT_EQ(tsv_float(file, rows[i], 6), t.alpha_tip) << want;
    EXPECT_EQ(tsv_float(file, rows[i], 7), t.alpha_body) << want;
    EXPECT_EQ(tsv_float(file, rows[i], 8), t.theta_before_per_s) << want;
    EXPECT_EQ(tsv_float(file, rows[i], 9), t.theta_after_per_s) << want;
    EXPECT_EQ(tsv_float(file, rows[i], 10), t.c) << want;
    EXPECT_GE(t.fap_value[4], 0.0f) << "tongue_roll is unidirectional";
  }
}

// Tongue values at the middle of each target phone.
Eigen::MatrixXf tongue_at_centres(const std::vector<std::pair<Phone, int>>& spec) {
  const TargetTimeline t = place_on_voice_grid(phones(spec), kSampleRate);
  const Eigen::MatrixXf track = tongue_track(t.phones, t.phone_of);
  Eigen::MatrixXf out(static_cast<Eigen::Index>(t.phones.size()), 5);
  for (std::size_t i = 0; i < t.phones.size(); ++i)
    out.row(static_cast<Eigen::Index>(i)) = track.row((t.phones[i].first_frame + t.phones[i].end_frame) / 2);
  return out;
}

TEST(Tongue, PlacesOfArticulationShow) {
  // columns: 0 shift, 1 raise tip, 2 thrust tip, 3 raise body, 4 roll
  const auto v = tongue_at_centres({{Phone::SIL, 150}, {Phone::AA, 150}, {Phone::T, 100}, {Phone::AA, 150},
                                    {Phone::TH, 110}, {Phone::AA, 150}, {Phone::K, 100}, {Phone::AA, 150},
                                    {Phone::IY, 150}, {Phone::SIL, 150}});
  EXPECT_GT(v(2, 1), 300.0f) << "/t/: tip up";
  EXPECT_GT(v(2, 1), v(1, 1) + 250.0f);
  EXPECT_GT(v(4, 2), 60.0f) << "/th/: tip forward";
  EXPECT_GT(v(4, 2), v(2, 2) + 40.0f);
  EXPECT_GT(v(6, 3), 300.0f) << "/k/: back up";
  EXPECT_LT(v(6, 1), v(2, 1) - 300.0f) << "/k/: tip not up";
  EXPECT_LT(v(1, 3), 0.0f) << "/aa/: tongue low";
  EXPECT_GT(v(8, 3), 250.0f) << "/iy/: body high";
  EXPECT_EQ(v(0, 0), 0.0f);
}

// The track is the model's definition, F(t) = sum D_s(t - c_s) T_s / sum D_s(t - c_s) over the
// phones within the reach (and always the phone on screen), evaluated here directly with
// Dominance::at: short phones, and a long silence whose own frames lie far past the reach.
TEST(Tongue, IsTheDominanceWeightedMeanOfTheTargets) {
  const TargetTimeline t = place_on_voice_grid(
      phones({{Phone::SIL, 30}, {Phone::T, 20}, {Phone::IY, 60}, {Phone::K, 25}, {Phone::SIL, 2000},
              {Phone::R, 70}, {Phone::UW, 120}, {Phone::S, 40}, {Phone::SIL, 40}}),
      kSampleRate);
  const Eigen::MatrixXf track = tongue_track(t.phones, t.phone_of);
  ASSERT_EQ(track.rows(), t.frame_count());
  for (Eigen::Index n = 0; n < track.rows(); ++n) {
    std::array<double, kTongueFapCount> num{}, den{};
    for (std::size_t s = 0; s < t.phones.size(); ++s) {
      const double tau = (2.0 * static_cast<double>(n) - static_cast<double>(t.phones[s].first_frame + t.phones[s].end_frame)) / 120.0;
      const bool on_screen = n >= t.phones[s].first_frame && n < t.phones[s].end_frame;
      // The reach as tongue_track tests it (exactly 0.4 s may fall either side of it in doubles).
      const double centre = 0.5 * static_cast<double>(t.phones[s].first_frame + t.phones[s].end_frame) / 60.0;
      if (!on_screen && std::abs(static_cast<double>(n) / 60.0 - centre) > kTongueReachS) continue;
      const TongueTarget& p = tongue_target(t.phone_of[s]);
      for (std::size_t f = 0; f < kTongueFapCount; ++f) {
        const double d = (f < 3 ? p.tip() : p.body()).at(tau);
        num[f] += d * p.fap_value[f];
        den[f] += d;
      }
    }
    for (std::size_t f = 0; f < kTongueFapCount; ++f)
      ASSERT_NEAR(track(n, static_cast<Eigen::Index>(f)), num[f] / den[f], 1e-3) << "frame " << n << " FAP " << 43 + f;
  }
}

TEST(Tongue, CoarticulatesAndFollowsTheTimeline) {
  // Anticipation: the tip is already rising in the vowel just before /t/.
  const TargetTimeline t = place_on_voice_grid(phones({{Phone::AA, 300}, {Phone::T, 80}, {Phone::AA, 300}}), kSampleRate);
  const Eigen::MatrixXf track = tongue_track(t.phones, t.phone_of);
  const auto before = t.phones[1].first_frame - 1, early = t.phones[0].first_frame + 2;
  EXPECT_GT(track(before, 1), track(early, 1) + 100.0f);
  // Continuous: no step larger than a fifth of the tip's travel between frames.
  for (Eigen::Index n = 1; n < track.rows(); ++n) EXPECT_LT(std::abs(track(n, 1) - track(n - 1, 1)), 120.0f) << n;
  EXPECT_THROW(tongue_track(t.phones, std::vector<Phone>{}), std::invalid_argument);
}

}  // namespace
}  // namespace fapcast
