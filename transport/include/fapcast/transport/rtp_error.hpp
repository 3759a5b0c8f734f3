#pragma once
// Why the RTP layer refused a packet or a call: std::error_code values in category "fapcast.rtp".
#include <system_error>

namespace fapcast {

enum class RtpErrc {
  kTruncatedHeader = 1,     // fewer than 12 bytes
  kBadVersion,              // version field is not 2
  kCsrcOverrun,             // the CSRC count points past the end of the packet
  kExtensionOverrun,        // the header extension length points past the end
  kBadPadding,              // padding count is 0 or larger than what follows the header
  kForeignSsrc,             // a source other than the one the receiver locked on
  kWrongPayloadType,        // not the payload type the receiver expects
  kMissingPayloadHeader,    // an FBA packet without its one-byte payload header
  kDuplicate,               // a sequence number already received
  kLate,                    // arrived after its sequence number was declared lost
  kSequenceJump,            // a jump larger than the receiver accepts (probation)
  kPayloadTooLarge,         // does not fit in one UDP datagram
  kBadRtcp,                 // an RTCP packet that is not a well-formed sender report
  kBadEndpoint,             // not udp://HOST:PORT
  kUndecodable,             // a source on probation sent a unit that does not decode
  kOutOfRun,                // a source on probation sent a packet outside its in-sequence run
};

const std::error_category& rtp_category() noexcept;
std::error_code make_error_code(RtpErrc e) noexcept;

}  // namespace fapcast

template <>
struct std::is_error_code_enum<fapcast::RtpErrc> : std::true_type {};
