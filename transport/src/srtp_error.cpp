#include "fapcast/transport/srtp_error.hpp"

#include <string>

namespace fapcast {
namespace {

class SrtpCategory final : public std::error_category {
 public:
  const char* name() const noexcept override { return "fapcast.srtp"; }
  std::string message(int value) const override {
    switch (static_cast<SrtpErrc>(value)) {
      case SrtpErrc::kAuthFailed: return "srtp-auth: authentication tag does not match (spoofed, tampered or another key)";
      case SrtpErrc::kReplayed: return "srtp-replay: packet index already received or older than the replay window";
      case SrtpErrc::kMalformed: return "srtp-malformed: not an SRTP packet";
      case SrtpErrc::kTooLarge: return "srtp-too-large: the protected packet does not fit in one datagram";
      case SrtpErrc::kFailed: return "srtp-failed: libsrtp refused the packet";
    }
    return "srtp: unknown error " + std::to_string(value);
  }
};

}  // namespace

const std::error_category& srtp_category() noexcept {
  static const SrtpCategory category;
  return category;
}

std::error_code make_error_code(SrtpErrc e) noexcept { return {static_cast<int>(e), srtp_category()}; }

}  // namespace fapcast
