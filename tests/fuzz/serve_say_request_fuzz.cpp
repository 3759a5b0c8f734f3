// Fuzzes parse_say_request (the body of POST /v1/say): any body either parses or is refused with
// RequestError 400 or 413 and a rule of the documented list, whose answer body is JSON that reads
// back to the same rule; what parses keeps the documented bounds, and the same request written
// back as JSON (text, lang, voice, channel, rtp, barge_in) parses to the same fields.
#include "fapcast/serve/request_error.hpp"
#include "fapcast/serve/say_request.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace {

constexpr std::array<std::string_view, 18> kRules = {
    "json-malformed", "json-too-deep",  "json-not-object",    "unknown-field", "field-type",  "text-missing",
    "text-empty",     "text-invalid",   "lang-unsupported",   "ssml-unsupported", "expression-invalid",
    "voice-invalid",  "rtp-url",        "rtp-too-many",       "srtp-key-invalid", "channel-invalid",
    "text-too-long",  "text-too-long"};

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
  if (r.srtp_key && r.rtp.empty()) __builtin_trap();
  bool known_lang = false;
  for (const auto l : supported_languages()) known_lang |= r.lang == l;
  if (!known_lang) __builtin_trap();

  nlohmann::json again = {{"text", r.text}, {"lang", r.lang}, {"voice", r.voice}, {"channel", r.channel},
                          {"barge_in", r.barge_in}};
  if (!r.rtp.empty()) {
    again["rtp"] = nlohmann::json::array();
    for (const auto& u : r.rtp) again["rtp"].push_back(url_text(u));
  }
  const SayRequest back = parse_say_request(again.dump(), limits);
  if (back.text != r.text || back.lang != r.lang || back.voice != r.voice || back.channel != r.channel ||
      back.barge_in != r.barge_in || back.rtp != r.rtp)
    __builtin_trap();
  return 0;
}
