// Fuzzes parse_srtp_key (the text of --srtp-key-file): any input either parses or is refused with
// InputError; what parses is 30 bytes whose base64 text parses to the same key, with and without
// the SDP "inline:" prefix.
#include "fapcast/core/input_error.hpp"
#include "fapcast/transport/srtp_key.hpp"

#include <cstdint>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapcast;
  SrtpMasterKey key;
  try {
    key = parse_srtp_key(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.key");
  } catch (const InputError&) {
    return 0;
  }
  const std::string text = srtp_key_text(key);
  if (text.size() != 40) __builtin_trap();
  if (parse_srtp_key(text, "again") != key || parse_srtp_key("inline:" + text, "again") != key) __builtin_trap();
  return 0;
}
