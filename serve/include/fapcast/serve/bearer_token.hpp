#pragma once
// The shared secret of `fapcast serve` (RFC 6750 bearer token): read from a file, compared in
// constant time, presented as "Authorization: Bearer TOKEN" on HTTP and on the WebSocket upgrade,
// or, from a browser (which cannot set that header on a WebSocket), as the subprotocol
// "bearer.TOKEN" beside "fapcast.v1" (spec/serve.md, "Who may use it").
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace fapcast {

// At least this many characters: 128 bits of base64 is 22.
inline constexpr std::size_t kMinTokenLength = 16;
inline constexpr std::size_t kMaxTokenLength = 512;

class BearerToken {
 public:
  // The token text: kMinTokenLength..kMaxTokenLength characters of A-Z a-z 0-9 - . _ ~ +
  // (RFC 6750's token68 that is also an RFC 7230 token, as a WebSocket subprotocol must be).
  // Throws InputError (source, byte offset, rule serve-token) otherwise.
  BearerToken(std::string_view text, const std::string& source);
  // The file holds the token on one line (a final newline allowed). Throws InputError naming the
  // file, std::runtime_error when it cannot be read.
  static BearerToken from_file(const std::filesystem::path& path);

  // Whether `presented` is the token. The time taken depends on the token's length only, never
  // on where the two first differ.
  bool matches(std::string_view presented) const;

 private:
  std::string token_;
};

// The credentials of an Authorization header value "Bearer TOKEN" (scheme case-insensitive), or
// nothing for any other form.
std::optional<std::string_view> bearer_credentials(std::string_view authorization);

// The token a browser offers in Sec-WebSocket-Protocol ("fapcast.v1, bearer.TOKEN"), or nothing.
std::optional<std::string_view> subprotocol_token(std::string_view protocols);
// Whether that header offers the subprotocol "fapcast.v1".
bool offers_live_subprotocol(std::string_view protocols);
inline constexpr std::string_view kLiveSubprotocol = "fapcast.v1";

}  // namespace fapcast
