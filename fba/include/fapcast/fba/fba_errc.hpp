#pragma once
// Why an FBA stream was refused (spec/fba.md). These are faults of the stream or of the data
// handed to the encoder; a caller's own mistake (an empty access unit, an invalid option) is
// reported as std::errc::invalid_argument instead, so the two can be told apart.
#include <system_error>

namespace fapcast {

enum class fba_errc {
  ok = 0,
  truncated = 1,              // the bits end before the plane does
  bad_start_code,             // a unit does not begin with the expected start code
  stuffing_bit_missing,       // 22 zeros not followed by the stuffed 1
  marker_bit_missing,         // a marker bit reads 0
  unsupported_object,         // fba_object_mask other than 1 (FAP only)
  dct_coding_unsupported,     // coding_type 1: the DCT (segment) coding is not implemented
  predicted_without_intra,    // a P plane with no intra plane to predict from
  bad_frame_rate,             // frame_rate 0 and seconds 0 (no rate)
  bad_time_code,              // minutes or seconds above 59
  skip_too_long,              // more skipped frames than kMaxSkipFrames
  trailing_bytes,             // bytes after the end of a plane's bits
  missing_object_start_code,  // a file that does not open with 0x000001BA
  missing_end_code,           // a file that does not close with 0x000001B1
  uncodable_value,            // encoder: a value beyond the codable range (never clipped)
  uncodable_frame_rate,       // encoder: a rate frame_rate(8)/seconds(4)[*1000/1001] cannot hold
  bad_frame_number,           // an intra plane's frame_number is not the frame it lands on
  bad_stuffing,               // a start code not after next_start_code() stuffing (0, then 1s)
  viseme_range,               // a P plane takes a viseme field out of its range
  expression_range,           // a P plane takes an expression field out of its range
  fapcast_profile,            // the standard-only path met a fapcast-profile stream
  bad_profile_version,        // a fapcast-profile stream of a version this decoder does not know
  bad_field,                  // a fapcast-profile header field out of its range
};

const std::error_category& fba_category();
std::error_code make_error_code(fba_errc e);

}  // namespace fapcast

template <>
struct std::is_error_code_enum<fapcast::fba_errc> : std::true_type {};
