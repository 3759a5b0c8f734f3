#include "fapcast/transport/rtp_error.hpp"

#include <string>

#include "fapcast/core/error_category.hpp"

namespace fapcast {
namespace {

std::string message_of(int value) {
  switch (static_cast<RtpErrc>(value)) {
    case RtpErrc::kTruncatedHeader: return "rtp-truncated-header: fewer than 12 bytes";
    case RtpErrc::kBadVersion: return "rtp-version: version is not 2";
    case RtpErrc::kCsrcOverrun: return "rtp-csrc-count: CSRC list runs past the packet";
    case RtpErrc::kExtensionOverrun: return "rtp-extension-length: extension runs past the packet";
    case RtpErrc::kBadPadding: return "rtp-padding: padding count is 0 or exceeds the payload";
    case RtpErrc::kForeignSsrc: return "rtp-foreign-ssrc: not the synchronisation source locked on";
    case RtpErrc::kWrongPayloadType: return "rtp-payload-type: unexpected payload type";
    case RtpErrc::kMissingPayloadHeader: return "rtp-payload-header: FBA payload header missing";
    case RtpErrc::kDuplicate: return "rtp-duplicate: sequence number already received";
    case RtpErrc::kLate: return "rtp-late: arrived after being declared lost";
    case RtpErrc::kSequenceJump: return "rtp-sequence-jump: sequence number far from the expected one";
    case RtpErrc::kPayloadTooLarge: return "rtp-too-large: does not fit in one datagram";
    case RtpErrc::kBadRtcp: return "rtcp-malformed: not a well-formed RTCP sender report";
    case RtpErrc::kBadEndpoint: return "udp-url: expected udp://HOST:PORT";
    case RtpErrc::kUndecodable: return "rtp-probation-undecodable: a unit of a source on probation does not decode";
    case RtpErrc::kOutOfRun: return "rtp-probation-sequence: not in sequence with the source's probation run";
  }
  return "rtp: unknown error " + std::to_string(value);
}

}  // namespace

const std::error_category& rtp_category() noexcept {
  static const NamedErrorCategory category("fapcast.rtp", message_of);
  return category;
}

std::error_code make_error_code(RtpErrc e) noexcept { return {static_cast<int>(e), rtp_category()}; }

}  // namespace fapcast
