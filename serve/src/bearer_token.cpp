#include "fapcast/serve/bearer_token.hpp"

#include "fapcast/core/file_io.hpp"
#include "fapcast/core/input_error.hpp"

#include <cctype>

namespace fapcast {
namespace {

// RFC 6750's token68 without '/' and '=': what is also an RFC 7230 token, so that a browser may
// offer it as a WebSocket subprotocol.
bool token_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' || c == '_' || c == '~' || c == '+';
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// Calls f on each comma-separated, trimmed item of a header value.
template <typename F>
void each_item(std::string_view list, F f) {
  while (!list.empty()) {
    const auto comma = list.find(',');
    const std::string_view item = trim(list.substr(0, comma));
    if (!item.empty() && f(item)) return;
    if (comma == std::string_view::npos) return;
    list.remove_prefix(comma + 1);
  }
}

constexpr std::string_view kBearerPrefix = "bearer.";

}  // namespace

BearerToken::BearerToken(std::string_view text, const std::string& source) {
  const auto fail = [&](std::size_t at, const std::string& detail) {
    return InputError({source, std::nullopt, at}, "serve-token", detail);
  };
  if (text.size() < kMinTokenLength || text.size() > kMaxTokenLength)
    throw fail(0, std::to_string(text.size()) + " characters; a token has " + std::to_string(kMinTokenLength) + ".." +
                      std::to_string(kMaxTokenLength) + " (e.g. `head -c 24 /dev/urandom | base64 | tr +/ -_`)");
  for (std::size_t i = 0; i < text.size(); ++i)
    if (!token_char(text[i]))
      throw fail(i, "character " + std::to_string(static_cast<unsigned char>(text[i])) +
                        " is not in the token alphabet (A-Z a-z 0-9 - . _ ~ +)");
  token_ = std::string(text);
}

BearerToken BearerToken::from_file(const std::filesystem::path& path) {
  // A file longer than a token and its line end breaks the token rule (not a read failure).
  std::error_code ec;
  if (const auto size = std::filesystem::file_size(path, ec); !ec && size > kMaxTokenLength + 2)
    throw InputError({path.string(), std::nullopt, kMaxTokenLength}, "serve-token",
                     std::to_string(size) + " bytes; a token file holds one token of " + std::to_string(kMinTokenLength) +
                         ".." + std::to_string(kMaxTokenLength) + " characters and its line end");
  std::string text = read_file(path, kMaxTokenLength + 3);
  if (!text.empty() && text.back() == '\n') text.pop_back();
  if (!text.empty() && text.back() == '\r') text.pop_back();
  return BearerToken(text, path.string());
}

bool BearerToken::matches(std::string_view presented) const {
  // Every byte of the token is compared whatever the presented text holds, and the lengths are
  // folded in at the end: no early exit, no branch on the data.
  volatile unsigned char difference = 0;
  const std::size_t n = presented.size();
  for (std::size_t i = 0; i < token_.size(); ++i) {
    const unsigned char p = n == 0 ? 0 : static_cast<unsigned char>(presented[i % n]);
    difference = static_cast<unsigned char>(difference | (p ^ static_cast<unsigned char>(token_[i])));
  }
  return (difference | static_cast<unsigned char>(n != token_.size())) == 0;
}

std::optional<std::string_view> bearer_credentials(std::string_view authorization) {
  authorization = trim(authorization);
  constexpr std::string_view scheme = "bearer";
  if (authorization.size() <= scheme.size() + 1) return std::nullopt;
  for (std::size_t i = 0; i < scheme.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(authorization[i])) != scheme[i]) return std::nullopt;
  if (authorization[scheme.size()] != ' ') return std::nullopt;
  const std::string_view token = trim(authorization.substr(scheme.size() + 1));
  if (token.empty() || token.find(' ') != std::string_view::npos) return std::nullopt;
  return token;
}

std::optional<std::string_view> subprotocol_token(std::string_view protocols) {
  std::optional<std::string_view> found;
  each_item(protocols, [&](std::string_view item) {
    if (item.substr(0, kBearerPrefix.size()) != kBearerPrefix || item.size() == kBearerPrefix.size()) return false;
    found = item.substr(kBearerPrefix.size());
    return true;
  });
  return found;
}

bool offers_live_subprotocol(std::string_view protocols) {
  bool found = false;
  each_item(protocols, [&](std::string_view item) { return found = item == kLiveSubprotocol; });
  return found;
}

}  // namespace fapcast
