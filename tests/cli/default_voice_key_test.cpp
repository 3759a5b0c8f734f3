// The default voice's cache key (cli/default_voice_key.hpp, spec/voice.md "The default voice"):
// another talker table or build recipe names another cache file, so a voice cached from older
// tables is never used.
#include "default_voice_key.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

#include "cli/fapcast_command.hpp"
#include "fapcast/core/file_io.hpp"
#include "support/run_command.hpp"

namespace fapcast {
namespace {

std::vector<PhoneChannelTarget> articulation() {
  const auto t = articulation_table();
  return {t.begin(), t.end()};
}
std::vector<ChannelShapeRow> shapes() {
  const auto t = channel_shape_table();
  return {t.begin(), t.end()};
}
std::vector<PrototypeShapeWeight> details() {
  const auto t = target_prototype_details();
  return {t.begin(), t.end()};
}

TEST(DefaultVoiceKey, IsTheCompiledTablesKeyAndFollowsEveryTable) {
  const std::string key = cli::default_voice_key(1);
  ASSERT_EQ(key.size(), 8u);
  EXPECT_EQ(key.find_first_not_of("0123456789abcdef"), std::string::npos) << key;
  EXPECT_EQ(key, cli::default_voice_key(1, articulation(), shapes(), details()));
  EXPECT_NE(key, cli::default_voice_key(2));

  auto a = articulation();
  a[8].target += 0.01f;  // AA's jaw target
  EXPECT_NE(key, cli::default_voice_key(1, a, shapes(), details()));
  a = articulation();
  a[9].dominance.alpha *= 2.0f;
  EXPECT_NE(key, cli::default_voice_key(1, a, shapes(), details()));
  auto s = shapes();
  s[5].weight = 0.8f;  // rounding -> mouthPucker
  EXPECT_NE(key, cli::default_voice_key(1, articulation(), s, details()));
  s = shapes();
  s.pop_back();
  EXPECT_NE(key, cli::default_voice_key(1, articulation(), s, details()));
  auto d = details();
  d[0].weight += 0.001f;
  EXPECT_NE(key, cli::default_voice_key(1, articulation(), shapes(), d));
}

// `voice default` takes the voice cached under the key and only that: a file of the old,
// unkeyed name (a voice of earlier tables) beside it is ignored.
TEST(DefaultVoiceKey, VoiceDefaultUsesTheKeyedCacheFile) {
  const std::filesystem::path dir = test::make_temp_dir("default-voice-key");
  const std::filesystem::path keyed = dir / ("reference-seed1-" + cli::default_voice_key(1) + ".fapv");
  write_file_atomically(dir / "reference-seed1.fapv", "an older talker's voice");
  write_file_atomically(keyed, "the current tables' voice");
  const auto r = test::run_command("FAPCAST_CACHE_DIR='" + dir.string() + "' " + test::fapcast("voice default -q"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, keyed.string() + "\n");
}

}  // namespace
}  // namespace fapcast
