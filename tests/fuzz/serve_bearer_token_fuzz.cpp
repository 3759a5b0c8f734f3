// Fuzzes the bearer token: BearerToken::from_file (the --token-file reader) and the header
// parsers (Authorization, Sec-WebSocket-Protocol). A file is either read or refused with
// InputError (rule serve-token, naming the file); a token read matches exactly its own text, not
// a text one character longer, shorter or changed. The header parsers return pieces of their
// input without blanks or commas.
#include "fapcast/core/input_error.hpp"
#include "fapcast/serve/bearer_token.hpp"

#include "fuzz/support/scratch_file.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace {
bool inside(std::string_view part, std::string_view whole) {
  return part.data() >= whole.data() && part.data() + part.size() <= whole.data() + whole.size();
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapcast;
  const std::string_view text(reinterpret_cast<const char*>(data), size);

  const auto path = fuzz::scratch_file("token", text);
  std::optional<BearerToken> token;
  try {
    token.emplace(BearerToken::from_file(path));
  } catch (const InputError& e) {
    if (e.rule() != "serve-token" || e.where().source != path.string()) __builtin_trap();
  }
  if (token) {
    std::string_view t = text;
    if (t.ends_with('\n')) t.remove_suffix(1);
    if (t.ends_with('\r')) t.remove_suffix(1);
    if (t.size() < kMinTokenLength || t.size() > kMaxTokenLength) __builtin_trap();
    if (!token->matches(t)) __builtin_trap();
    std::string longer(t);
    longer.push_back('a');
    if (token->matches(longer) || token->matches(t.substr(0, t.size() - 1)) || token->matches("")) __builtin_trap();
    std::string changed(t);
    changed[size % changed.size()] ^= 1;
    if (token->matches(changed)) __builtin_trap();
  }

  if (const auto c = bearer_credentials(text)) {
    if (c->empty() || !inside(*c, text) || c->find(' ') != std::string_view::npos) __builtin_trap();
  }
  if (const auto s = subprotocol_token(text)) {
    if (s->empty() || !inside(*s, text) || s->find(',') != std::string_view::npos) __builtin_trap();
  }
  (void)offers_live_subprotocol(text);
  return 0;
}
