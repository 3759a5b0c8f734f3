#pragma once
// The 68 facial animation parameters (FAPs) of MPEG-4 face animation, as constexpr data.
// Facts gathered from public players and codecs that read and write FAP data (spec/fap-text.md);
// spec/faps.tsv is the machine-readable copy that a test checks this table against.
#include "fapcast/codec/feature_point.hpp"
#include "fapcast/codec/fapu.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace fapcast {

inline constexpr int kFapCount = 68;    // FAPs are numbered 1..68
// FAP n's place in an array over all kFapCount FAPs (values[n - 1]).
constexpr std::size_t fap_slot(int fap) { return static_cast<std::size_t>(fap - 1); }
inline constexpr int kGroupCount = 10;  // FAP groups are numbered 1..10
inline constexpr int kVisemeFap = 1;
inline constexpr int kExpressionFap = 2;
inline constexpr int kFirstLowLevelFap = 3;

// One FAP's row in the standard's table.
struct FapInfo {
  int number;                  // 1..68
  std::string_view name;       // the standard's name, e.g. "open_jaw"
  Fapu unit;                   // the FAPU its values are measured in (kNone for FAP 1, 2)
  bool unidirectional;         // only >= 0 expected; readers must still accept negatives
  std::string_view direction;  // direction of positive values: "down", "left", "forward" ...
  int group;                   // 1..10
  std::optional<FeaturePoint> feature_point;  // the point it moves; none for eyeballs, head
  std::optional<FeaturePoint> also_moves;     // a second point (tongue_roll moves 6.3 and 6.4)
  int qp;                      // quantiser step scale (step = qp * fap_quant)
  int range_i;                 // default coding range in quantised units, intra frames
  int range_p;                 // ... and predicted frames
};

// All 68 rows, index n-1 for FAP n.
std::span<const FapInfo, kFapCount> fap_table();

// FAP n (1..68). Precondition: 1 <= n <= 68.
const FapInfo& fap_info(int number);

// FAP by its standard name; nullopt when no FAP has that name.
std::optional<int> fap_number(std::string_view name);

// The first and last FAP number of group g (1..10): group 2 is FAPs 3..18.
struct FapRange {
  int first;
  int last;
};
FapRange fap_group(int group);

}  // namespace fapcast
