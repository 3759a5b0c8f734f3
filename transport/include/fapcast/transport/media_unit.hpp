#pragma once
// One unit of media ready for RTP: its bytes and its position on the media timeline.
#include <cstdint>
#include <vector>

namespace fapcast {

struct MediaUnit {
  std::int64_t sample = 0;          // position on the timeline, in samples of the RTP clock (>= 0)
  std::vector<std::uint8_t> bytes;  // one FBA access unit (or opaque bytes in tests)
  bool intra = false;               // decodable without any earlier unit
  bool fapcast = false;             // an FBA unit of the fapcast profile (spec/fba.md §9)
  bool operator==(const MediaUnit&) const = default;
};

}  // namespace fapcast
