#pragma once
// Why SRTP refused a packet: std::error_code values in category "fapcast.srtp".
#include <system_error>

namespace fapcast {

enum class SrtpErrc {
  kAuthFailed = 1,  // the authentication tag does not match: spoofed, tampered or another key
  kReplayed,        // an index already received, or older than the replay window
  kMalformed,       // too short to be SRTP/SRTCP, or a header libsrtp refuses
  kTooLarge,        // protected, the packet would not fit in one datagram
  kFailed,          // libsrtp refused for another reason (its status is in the message)
};

const std::error_category& srtp_category() noexcept;
std::error_code make_error_code(SrtpErrc e) noexcept;

}  // namespace fapcast

template <>
struct std::is_error_code_enum<fapcast::SrtpErrc> : std::true_type {};
