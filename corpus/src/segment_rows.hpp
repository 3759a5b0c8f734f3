#pragma once
// Private helpers of the segment-list readers (ESPS, TIMIT, MLF, Partitur, Gentle): the order
// rule they share, the segment limit, times for messages.
#include "fapcast/corpus/label_tier.hpp"

#include <cstdint>
#include <string>
#include <string_view>

namespace fapcast::detail {

inline constexpr std::size_t kMaxSegments = std::size_t{1} << 21;  // 10 h of phones at 50 per second

// An optionally signed decimal integer.
bool parse_signed(std::string_view s, std::int64_t& v);

// Seconds for messages: up to 6 decimals (1 us), no float noise ("0.1", not 0.09999999999999999).
std::string time_text(double s);

// The order every segment list shares, for the segment just appended to `t`: it starts at or
// after 0 and ends at or after its start, no overlap with the previous segment (gaps and
// zero-length segments are allowed), at most kMaxSegments. Throws InputError at `line`.
void check_segment_order(const LabelTier& t, const std::string& source, std::uint64_t line, const std::string& rule);

// Makes `t` an interval tier spanning [0, its last end].
void close_segment_tier(LabelTier& t);

}  // namespace fapcast::detail
