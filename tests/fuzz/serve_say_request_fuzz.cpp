// Fuzzes parse_say_request (the body of POST /v1/say): any body either parses or is refused with
// RequestError 400 or 413 and a rule of the documented list, whose answer body is JSON that reads
// back to the same rule; what parses keeps the documented bounds, and the same request written
// back as JSON (text or ssml, lang, voice, channel, rtp, srtp, interrupt) parses to the same fields,
// and its sentence offsets cut the text in increasing order within it.
#include "fapcast/serve/request_error.hpp"
#include "fapcast/serve/say_request.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace {

constexpr std::array<std::string_view, 17> kRules = {
    "json-malformed", "json-too-deep",   "json-not-object", "unknown-field",  "field-type",   "text-missing",
    "text-twice",     "text-empty",      "text-invalid",    "lang-invalid",   "expression-invalid",
    "voice-invalid",  "rtp-url",         "rtp-too-many",    "srtp-without-rtp", "channel-invalid",
    "text-too-long"};

bool known_rule(const std::string& rule) {
  for (const auto r : kRules)
    if (rule == r) return true;
  return false;
}

std::string url_text(const fapcast::UdpUrl& u) {
  const bool v6 = u.host.find(':') != std::string::npos;
  return "udp://" + (v6 ? "[" + u.host + "]" : u.host) + ":" + std::to_string(u.port);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapcast;
  // Small limits so that the bounds are reached by short inputs too.
  const SayLimits limits{.max_text_bytes = 64, .max_rtp_destinations = 2};
  const std::string_view body(reinterpret_cast<const char*>(data), size);
  SayRequest r;
  try {
    r = parse_say_request(body, limits);
  } catch (const RequestError& e) {
    if (!known_rule(e.rule())) __builtin_trap();
    if (e.status() != (e.rule() == "text-too-long" ? 413 : 400)) __builtin_trap();
    const auto answer = nlohmann::json::parse(request_error_body(e), nullptr, false);
    if (answer.is_discarded() || answer.value("error", std::string()) != e.rule()) __builtin_trap();
    return 0;
  }
  if (r.text.empty() || r.text.size() > limits.max_text_bytes) __builtin_trap();
  if (!valid_name(r.voice) || !valid_name(r.channel)) __builtin_trap();
  if (r.rtp.size() > limits.max_rtp_destinations) __builtin_trap();
  if (r.srtp.value_or(false) && r.rtp.empty()) __builtin_trap();
  const auto offsets = sentence_offsets(r);
  if (offsets.empty()) __builtin_trap();
  for (std::size_t i = 0; i < offsets.size(); ++i)
    if (offsets[i] > r.text.size() || (i > 0 && offsets[i] <= offsets[i - 1])) __builtin_trap();

  nlohmann::json again = {{r.ssml ? "ssml" : "text", r.text}, {"lang", r.lang}, {"voice", r.voice},
                          {"channel", r.channel}, {"interrupt", r.interrupt}};
  if (r.srtp) again["srtp"] = *r.srtp;
  if (!r.rtp.empty()) {
    again["rtp"] = nlohmann::json::array();
    for (const auto& u : r.rtp) again["rtp"].push_back(url_text(u));
  }
  const SayRequest back = parse_say_request(again.dump(), limits);
  if (back.text != r.text || back.ssml != r.ssml || back.lang != r.lang || back.voice != r.voice ||
      back.channel != r.channel || back.interrupt != r.interrupt || back.srtp != r.srtp || back.rtp != r.rtp)
    __builtin_trap();
  return 0;
}
