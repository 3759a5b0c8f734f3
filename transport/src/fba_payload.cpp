#include "fapcast/transport/fba_payload.hpp"

#include "fapcast/transport/rtp_error.hpp"

namespace fapcast {

void pack_fba_payload(bool intra, bool fapcast, std::span<const std::uint8_t> access_unit,
                      std::vector<std::uint8_t>& out) {
  out.push_back(static_cast<std::uint8_t>((intra ? kFbaIntraFlag : 0) | (fapcast ? kFbaFapcastFlag : 0)));
  out.insert(out.end(), access_unit.begin(), access_unit.end());
}

std::error_code parse_fba_payload(std::span<const std::uint8_t> payload, FbaPayload& out) {
  if (payload.empty()) return RtpErrc::kMissingPayloadHeader;
  out.intra = (payload[0] & kFbaIntraFlag) != 0;
  out.fapcast = (payload[0] & kFbaFapcastFlag) != 0;
  out.access_unit = payload.subspan(1);
  return {};
}

}  // namespace fapcast
