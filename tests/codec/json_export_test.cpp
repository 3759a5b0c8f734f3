#include "fapcast/codec/json_export.hpp"

#include "fapcast/codec/face_geometry.hpp"
#include "fapcast/core/input_error.hpp"
#include "support/bad_inputs.hpp"
#include "support/fap_sequences.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <random>

namespace fapcast {
namespace {

namespace fs = std::filesystem;
const fs::path kDir = fs::path(FAPCAST_TEST_DATA) / "json";

// The sequence tests/data/json/small.json holds (spec/json.md shows it).
FapSequence small_sequence() {
  FapSequence s{"hello", {25, 1}, {}};
  for (int k = 0; k < 3; ++k) {
    FapFrame f;
    f.set(3, 120 * k).set(4, -10 * k).set(53, 25 * k);
    if (k == 1) f.mask.set(kVisemeFap), f.viseme = {1, 10, 40, false};
    if (k == 2) f.mask.set(kExpressionFap), f.expression = {1, 40, 0, 0, false, false};
    s.frames.push_back(f);
  }
  return s;
}

FapJsonOptions small_options() {
  return {SampleRate{16000}, measure_fapu(generic_adult_face().feature_points), "fapcast 0.1.0"};
}

TEST(FapJson, WritesTheGoldenFileByteForByte) {
  EXPECT_EQ(write_fap_json(small_sequence(), small_options()), test::slurp(kDir / "small.json"));
}

TEST(FapJson, SpecExampleIsTheGoldenFile) {
  const std::string spec = test::slurp(fs::path(FAPCAST_SOURCE_DIR) / "spec" / "json.md");
  const auto start = spec.find("```json\n") + 8;
  EXPECT_EQ(spec.substr(start, spec.find("```", start) - start), test::slurp(kDir / "small.json"));
}

TEST(FapJson, ReadsTheGoldenFile) {
  const FapJsonRead r = read_fap_json(test::slurp(kDir / "small.json"), "small.json");
  EXPECT_EQ(r.sequence, small_sequence());
  EXPECT_EQ(r.options.sample_rate, SampleRate{16000});
  EXPECT_EQ(r.options.fapu, small_options().fapu);
  EXPECT_EQ(r.options.generator, "fapcast 0.1.0");
}

TEST(FapJson, IsPlainJsonWithNamedFapsTimesAndSamples) {
  // What a web player sees, read with a general JSON parser rather than ours.
  const auto j = nlohmann::json::parse(write_fap_json(small_sequence(), small_options()));
  EXPECT_EQ(j["fps"], 25.0);
  EXPECT_EQ(j["frame_count"], 3);
  EXPECT_EQ(j["frames"][2]["faps"]["open_jaw"], 240);
  EXPECT_EQ(j["frames"][2]["time_s"], 0.08);
  EXPECT_EQ(j["frames"][2]["sample"], 1280);
  EXPECT_EQ(j["frames"][1]["viseme"]["select2"], 10);
  EXPECT_FALSE(j["frames"][0].contains("viseme"));
  EXPECT_EQ(j["fapu"]["MNS"], 2.2 / 1024);
}

TEST(FapJson, SamplePositionsAreTheExactTimelineAtNtscRates) {
  FapSequence seq{"ntsc", {30000, 1001}, std::vector<FapFrame>(3000)};
  const auto j = nlohmann::json::parse(write_fap_json(seq, {SampleRate{44100}, std::nullopt, "t"}));
  for (std::int64_t k = 0; k < 3000; ++k) {
    ASSERT_EQ(j["frames"][static_cast<std::size_t>(k)]["sample"].get<std::int64_t>(),
              frame_to_sample(k, {30000, 1001}, SampleRate{44100}));
    EXPECT_NEAR(j["frames"][static_cast<std::size_t>(k)]["time_s"].get<double>(),
                k * 1001.0 / 30000.0, 1e-12);
  }
  // 2997 frames last 99.9999 s: 4409995.59 samples at 44.1 kHz, rounded to the nearest.
  EXPECT_EQ(j["frames"][2997]["sample"], 4409996);
}

TEST(FapJson, RandomSequencesRoundTripExactly) {
  const std::uint64_t s = test::test_seed(test::kFapSequenceSeed);
  std::mt19937_64 rng(s);
  const std::optional<SampleRate> sample_rates[] = {std::nullopt, SampleRate{8000}, SampleRate{44100}, SampleRate{48000}};
  for (int i = 0; i < 200; ++i) {
    FapSequence seq = test::random_fap_sequence(rng, rng() % 40);
    if (i % 2) seq.name = "escapes: \"quoted\" \\ tab\t \xc3\xa9";  // JSON string escaping
    FapJsonOptions options;
    options.sample_rate = sample_rates[rng() % 4];
    if (rng() % 2) options.fapu = FapuValues{0.1, 0.2, 0.3, 0.4, 1e-9};
    const std::string text = write_fap_json(seq, options);
    const FapJsonRead back = read_fap_json(text, "random.json");
    ASSERT_EQ(back.sequence, seq) << "sequence " << i << "; reproduce with FAPCAST_SEED=" << s
                                  << " fapcast_codec_tests --gtest_filter=FapJson.*";
    ASSERT_EQ(back.options.sample_rate, options.sample_rate);
    ASSERT_EQ(back.options.fapu, options.fapu);
    ASSERT_EQ(write_fap_json(back.sequence, back.options), text);  // deterministic
  }
}

TEST(FapJson, WriterRefusesRatesItCannotPlaceOnATimeline) {
  EXPECT_THROW(write_fap_json(FapSequence{"x", {0, 1}, {}}), std::invalid_argument);
  EXPECT_THROW(write_fap_json(FapSequence{"x", {25, 1}, {}}, {SampleRate{0}, std::nullopt, "t"}),
               std::invalid_argument);
  EXPECT_THROW(write_fap_json(FapSequence{"x", {25, 1}, {}}, {SampleRate{kFapJsonMaxRate + 1}, std::nullopt, "t"}),
               std::invalid_argument);
}

class FapJsonBadInput : public testing::TestWithParam<std::string> {};

TEST_P(FapJsonBadInput, FailsWithItsRuleAndTheGoldenMessage) {
  const std::string name = GetParam();
  try {
    read_fap_json(test::slurp(kDir / "bad" / name), name);
    FAIL() << name << " was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.rule(), test::rule_of(name));
    EXPECT_EQ(e.where().source, name);
    EXPECT_EQ(e.what(), test::golden_errors(kDir / "bad")[name]);
  }
}

INSTANTIATE_TEST_SUITE_P(Named, FapJsonBadInput,
                         testing::ValuesIn(test::bad_input_names(kDir / "bad", ".json")),
                         [](const auto& info) { return test::test_name_of(info.param); });

TEST(FapJson, GoldenListCoversExactlyTheBadInputs) {
  const auto golden = test::golden_errors(kDir / "bad");
  const auto names = test::bad_input_names(kDir / "bad", ".json");
  EXPECT_EQ(golden.size(), names.size());
  for (const std::string& name : names) EXPECT_TRUE(golden.count(name)) << name;
}

TEST(FapJson, DeepNestingIsASyntaxOrTypeErrorNotACrash) {
  std::string deep = "{\"format\":" + std::string(200000, '[') + std::string(200000, ']') + "}";
  EXPECT_THROW(read_fap_json(deep, "deep.json"), InputError);
}

}  // namespace
}  // namespace fapcast
