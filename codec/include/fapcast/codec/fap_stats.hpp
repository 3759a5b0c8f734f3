#pragma once
// Summary statistics of a FAP sequence (duration, which FAPs move, and their value ranges),
// independent of the file format it came from: `fapcast fap info` prints them for .fap text
// and any later reader that yields a FapSequence.
#include "fapcast/codec/fap_frame.hpp"

#include <bitset>
#include <cstdint>
#include <vector>

namespace fapcast {

// One FAP over a sequence: in how many frames it is masked, and the smallest and largest value
// it takes there. For FAP 1 (viseme) and FAP 2 (expression) min/max are of select1.
struct FapValueRange {
  int fap = 0;                        // 1..68
  std::uint64_t frames_masked = 0;    // >= 1
  std::int32_t min = 0;               // in the FAP's FAPU (low-level FAPs)
  std::int32_t max = 0;
  bool operator==(const FapValueRange&) const = default;
};

struct FapStats {
  std::uint64_t frame_count = 0;
  FrameRate rate;
  std::int64_t duration_ms = 0;            // frame_count frames at `rate`, rounded to 1 ms
  std::vector<FapValueRange> masked_faps;  // every FAP masked in some frame, in FAP order
  std::bitset<15> visemes_used;     // visemes that contribute: select1, and select2 if blend < 63
  std::bitset<7> expressions_used;  // expressions: select1, and select2 if intensity2 > 0
  bool operator==(const FapStats&) const = default;
};

// Computes the statistics in one pass over the frames.
FapStats fap_stats(const FapSequence& seq);

}  // namespace fapcast
