#pragma once
// The FBA RTP payload (spec/rtp.md): a one-byte payload header |I|F|0 0 0 0 0 0| followed by
// exactly one FBA access unit. I = 1 marks an intra unit, so a receiver finds a resumption point
// without parsing the bitstream; F = 1 marks a unit of the fapcast profile (spec/fba.md §9), 0 the
// standard syntax; the six reserved bits are sent as 0 and ignored on receipt.
#include <cstdint>
#include <span>
#include <system_error>
#include <vector>

namespace fapcast {

inline constexpr std::uint8_t kFbaIntraFlag = 0x80;
inline constexpr std::uint8_t kFbaFapcastFlag = 0x40;

struct FbaPayload {
  bool intra = false;
  bool fapcast = false;  // the fapcast profile's syntax
  std::span<const std::uint8_t> access_unit;  // view into the packet
};

// Appends the payload header and the access unit to `out`.
void pack_fba_payload(bool intra, bool fapcast, std::span<const std::uint8_t> access_unit,
                      std::vector<std::uint8_t>& out);

// Splits a payload. Errors: RtpErrc::kMissingPayloadHeader for an empty payload.
std::error_code parse_fba_payload(std::span<const std::uint8_t> payload, FbaPayload& out);

}  // namespace fapcast
