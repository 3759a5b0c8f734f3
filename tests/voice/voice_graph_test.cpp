#include "fapcast/voice/voice_graph.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "fapcast/core/input_error.hpp"

namespace fapcast {
namespace {

// Two utterances: "sil B AA sil" over frames 0..9 and "S IY" over 10..15.
VoiceGraphData sample() {
  VoiceGraphData g;
  g.utterances = {{0, 10}, {10, 6}};
  g.frame_count = 16;
  const std::pair<Phone, FrameSpan> phones[] = {{Phone::SIL, {0, 2}}, {Phone::B, {2, 3}},  {Phone::AA, {5, 4}},
                                                {Phone::SIL, {9, 1}}, {Phone::S, {10, 3}}, {Phone::IY, {13, 3}}};
  for (std::size_t j = 0; j < std::size(phones); ++j) {
    g.states.push_back({j < 4 ? 0u : 1u, search_viseme(phones[j].first), phones[j].second});
    g.phones.push_back(phones[j].first);
  }
  return g;
}

std::string rule_of(const std::vector<std::byte>& bytes) {
  try {
    (void)decode_voice_graph(bytes, "voice.fapv", 1000);
  } catch (const InputError& e) {
    EXPECT_TRUE(e.where().offset.has_value());
    EXPECT_GE(*e.where().offset, 1000u) << "offsets are absolute in the file";
    return e.rule();
  }
  return "accepted";
}

template <class T>
void poke(std::vector<std::byte>& b, std::size_t at, T v) { std::memcpy(b.data() + at, &v, sizeof v); }

TEST(VoiceGraph, RoundTripsItsLayout) {
  const VoiceGraphData g = sample();
  const auto bytes = encode_voice_graph(g);
  EXPECT_EQ(bytes.size(), 16u + 16u * 6u + 8u * 2u);
  EXPECT_EQ(decode_voice_graph(bytes, "x", 0), g);
  // The layout is little-endian and fixed: state 1 (B) at byte 32.
  EXPECT_EQ(std::to_integer<int>(bytes[16 + 16 + 4]), 2);   // first frame
  EXPECT_EQ(std::to_integer<int>(bytes[16 + 16 + 8]), 3);   // frame count
  EXPECT_EQ(std::to_integer<int>(bytes[16 + 16 + 12]), static_cast<int>(VisemeClass::kBilabial));
  EXPECT_EQ(std::to_integer<int>(bytes[16 + 16 + 13]), static_cast<int>(Phone::B));
}

TEST(VoiceGraph, EncoderRefusesWhatTheDecoderWould) {
  VoiceGraphData g = sample();
  g.phones.pop_back();
  EXPECT_THROW((void)encode_voice_graph(g), std::invalid_argument);
  g = sample();
  g.states[1].viseme = VisemeClass::kDental;
  EXPECT_THROW((void)encode_voice_graph(g), std::invalid_argument);
}

TEST(VoiceGraph, DecoderNamesEveryRule) {
  const auto good = encode_voice_graph(sample());
  EXPECT_EQ(rule_of(good), "accepted");
  EXPECT_EQ(rule_of(std::vector<std::byte>(good.begin(), good.begin() + 12)), "graph-truncated");
  auto b = good;
  poke<std::uint32_t>(b, 0, 1);  // the 40-phone layout
  EXPECT_EQ(rule_of(b), "graph-version");
  b = good;
  poke<std::uint32_t>(b, 4, 0xFFFFFFFFu);  // a hostile count is checked against the size first
  EXPECT_EQ(rule_of(b), "graph-size");
  b = good;
  b.pop_back();
  EXPECT_EQ(rule_of(b), "graph-size");
  b = good;
  poke<std::uint32_t>(b, 12, 17);
  EXPECT_EQ(rule_of(b), "graph-span");  // utterances cover 16 frames
  b = good;
  poke<std::uint32_t>(b, 16 + 96 + 8, 11);  // utterance 1 starts at 11, not 10
  EXPECT_EQ(rule_of(b), "graph-span");
  b = good;
  poke<std::uint32_t>(b, 16 + 16 * 2, 5);  // state 2 in utterance 5 of 2
  EXPECT_EQ(rule_of(b), "graph-state");
  b = good;
  poke<std::uint8_t>(b, 16 + 16 * 2 + 13, 40);  // phone 40 of 40
  EXPECT_EQ(rule_of(b), "graph-state");
  b = good;
  poke<std::uint8_t>(b, 16 + 16 * 2 + 12, 1);  // AA tagged bilabial
  EXPECT_EQ(rule_of(b), "graph-state");
  b = good;
  poke<std::uint16_t>(b, 16 + 16 * 2 + 14, 1);  // reserved
  EXPECT_EQ(rule_of(b), "graph-state");
  b = good;
  poke<std::uint32_t>(b, 16 + 16 * 2 + 4, 3);  // AA starts inside B
  EXPECT_EQ(rule_of(b), "graph-order");
  b = good;  // states 3 (sil of utterance 0) and 4 (S of utterance 1) swapped
  std::swap_ranges(b.begin() + 16 + 16 * 3, b.begin() + 16 + 16 * 4, b.begin() + 16 + 16 * 4);
  EXPECT_EQ(rule_of(b), "graph-order");
  b = good;
  poke<std::uint32_t>(b, 16 + 16 * 3 + 8, 2);  // the last sil of utterance 0 runs into utterance 1
  EXPECT_EQ(rule_of(b), "graph-span");
  b = good;
  poke<std::uint32_t>(b, 16 + 16 * 3 + 8, 0);  // empty state
  EXPECT_EQ(rule_of(b), "graph-span");
}

}  // namespace
}  // namespace fapcast
