#pragma once
// The body of POST /v1/say (spec/serve.md, "POST /v1/say"): a JSON object whose keys are
// checked one by one, so that a request either means exactly one thing or is refused with a
// named rule before any work is done.
#include "fapcast/serve/request_error.hpp"
#include "fapcast/synthesis/speech_expression.hpp"
#include "fapcast/transport/udp_url.hpp"

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fapcast {

struct SayRequest {
  std::string text;                          // UTF-8 plain text ("text") or SSML ("ssml"); the front-end's rules
  bool ssml = false;                         // the text is SSML: espeak-ng parses the markup; spoken as one piece
  std::string lang = "en-us";                // the language espeak-ng speaks (the server checks it is installed)
  std::optional<ExpressionBlend> expression;  // FAP 2 with the speech ("joy:40[,surprise:20]")
  std::string voice = "default";             // a voice the server was started with
  std::vector<UdpUrl> rtp;                   // RTP destinations (udp://HOST:PORT), besides live clients
  std::optional<bool> srtp;                  // protect the RTP with the server's key; unset: whether it has one
  std::string channel = "default";           // the live clients and the queue it speaks on
  bool interrupt = false;                    // barge-in: stop what the channel is saying and drop its queue first
};

// The byte offsets where a session's text is cut into the pieces it speaks one at a time: the
// front-end's chunk_offsets at `max_bytes` (cut after sentence ends first, short sentences
// packed, a longer one cut at a space); SSML is one piece; white space only gives none.
inline constexpr std::size_t kDefaultSentenceBytes = 120;
std::vector<std::size_t> sentence_offsets(const SayRequest& request, std::size_t max_bytes = kDefaultSentenceBytes);

struct SayLimits {
  std::size_t max_text_bytes = 4 * 1024;
  std::size_t max_rtp_destinations = 4;
};

// A channel or voice name: 1..32 of a-z 0-9 - _.
bool valid_name(std::string_view name);

// Parses and checks a body. Throws RequestError (status, rule, detail):
//   400 json-malformed (with the byte offset), json-too-deep, json-not-object, unknown-field,
//       field-type, text-missing (neither "text" nor "ssml"), text-twice (both), text-empty,
//       text-invalid (the front-end's rule and byte), lang-invalid, expression-invalid,
//       voice-invalid, rtp-url, rtp-too-many, srtp-without-rtp, channel-invalid;
//   413 text-too-long.
// The checks that need the server (the voice exists, the destination is allowed) are its own.
SayRequest parse_say_request(std::string_view body, const SayLimits& limits);

}  // namespace fapcast
