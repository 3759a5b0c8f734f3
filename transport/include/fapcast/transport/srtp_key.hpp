#pragma once
// The master key of an SRTP session (RFC 3711) with the AES_CM_128_HMAC_SHA1_80 suite: a 16-byte
// AES key and a 14-byte salt, written as RFC 4568's key-params do, 30 bytes in 40 characters of
// base64, optionally after "inline:" (SDP a=crypto). spec/rtp.md section 7.
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace fapcast {

inline constexpr std::size_t kSrtpKeyBytes = 16;   // AES-128
inline constexpr std::size_t kSrtpSaltBytes = 14;  // 112-bit salt
inline constexpr std::size_t kSrtpMasterKeyBytes = kSrtpKeyBytes + kSrtpSaltBytes;

struct SrtpMasterKey {
  std::array<std::uint8_t, kSrtpMasterKeyBytes> bytes{};  // key, then salt
  bool operator==(const SrtpMasterKey&) const = default;
};

// Parses base64 of exactly 30 bytes, "inline:" allowed before it, spaces and tabs around it.
// Throws InputError at the byte offset in `text`: srtp-key-base64 (a character outside the
// base64 alphabet, or bad padding), srtp-key-length (not 30 bytes once decoded), srtp-key-weak
// (every byte the same: a placeholder, not a key).
SrtpMasterKey parse_srtp_key(std::string_view text, const std::string& source);
// The key file: one line holding the key as parse_srtp_key reads it (a final newline allowed).
// Throws InputError naming the file, std::runtime_error when it cannot be read.
SrtpMasterKey read_srtp_key_file(const std::filesystem::path& path);
// The 40-character base64 text (no "inline:").
std::string srtp_key_text(const SrtpMasterKey& key);
// A fresh key from std::random_device.
SrtpMasterKey random_srtp_key();

}  // namespace fapcast
