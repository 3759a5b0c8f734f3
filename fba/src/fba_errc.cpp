#include "fapcast/fba/fba_errc.hpp"

#include <string>

#include "fapcast/core/error_category.hpp"

namespace fapcast {
namespace {

std::string message_of(int code) {
  switch (static_cast<fba_errc>(code)) {
    case fba_errc::ok: return "ok";
    case fba_errc::truncated: return "truncated: the bits end before the plane does";
    case fba_errc::bad_start_code: return "bad-start-code: expected an object-plane start code or the end code";
    case fba_errc::stuffing_bit_missing: return "stuffing-bit-missing: 22 zeros not followed by a stuffed 1";
    case fba_errc::marker_bit_missing: return "marker-bit-missing: a marker bit is 0";
    case fba_errc::unsupported_object: return "unsupported-object: fba_object_mask is not 1 (FAP only)";
    case fba_errc::dct_coding_unsupported: return "dct-coding-unsupported: coding_type 1 (DCT) is not implemented";
    case fba_errc::predicted_without_intra: return "predicted-without-intra: a P plane with no intra plane before it";
    case fba_errc::bad_frame_rate: return "bad-frame-rate: frame_rate and seconds are 0";
    case fba_errc::bad_time_code: return "bad-time-code: minutes or seconds above 59";
    case fba_errc::skip_too_long: return "skip-too-long: more skipped frames than the decoder accepts";
    case fba_errc::trailing_bytes: return "trailing-bytes: bytes after the end of a plane or of the stream";
    case fba_errc::missing_object_start_code: return "missing-object-start-code: the file does not open with 0x000001BA";
    case fba_errc::missing_end_code: return "missing-end-code: the file does not close with 0x000001B1";
    case fba_errc::uncodable_value: return "uncodable-value: a value beyond the codable range";
    case fba_errc::uncodable_frame_rate: return "uncodable-frame-rate: the frame rate has no frame_rate/seconds form";
    case fba_errc::bad_frame_number: return "bad-frame-number: an intra plane's frame_number is not the frame it lands on";
    case fba_errc::bad_stuffing: return "bad-stuffing: a start code must follow next_start_code() stuffing (a 0, then 1s to the byte boundary)";
    case fba_errc::viseme_range: return "viseme-range: a P plane takes a viseme field out of its range";
    case fba_errc::expression_range: return "expression-range: a P plane takes an expression field out of its range";
    case fba_errc::fapcast_profile: return "fapcast-profile: a fapcast-profile stream (user data \"fapcast\"), not standard FBA: decode it without the standard-only option";
    case fba_errc::bad_profile_version: return "bad-profile-version: a fapcast-profile stream of an unknown version";
    case fba_errc::bad_field: return "bad-field: a fapcast-profile header field or level out of its range";
  }
  return "unknown fba error " + std::to_string(code);
}

}  // namespace

const std::error_category& fba_category() {
  static const NamedErrorCategory category("fba", message_of);
  return category;
}

std::error_code make_error_code(fba_errc e) { return {static_cast<int>(e), fba_category()}; }

}  // namespace fapcast
