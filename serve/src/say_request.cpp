#include "fapcast/serve/say_request.hpp"

#include "fapcast/core/input_error.hpp"
#include "fapcast/frontend/text_frontend.hpp"

#include <nlohmann/json.hpp>


namespace fapcast {
namespace {
using nlohmann::json;

constexpr int kMaxDepth = 3;  // {"rtp": ["udp://..."]} is depth 2

RequestError bad(const std::string& rule, const std::string& detail) { return RequestError(400, rule, detail); }

const std::string& string_field(const json& v, const char* key) {
  if (!v.is_string()) throw bad("field-type", std::string("'") + key + "' must be a string");
  return v.get_ref<const std::string&>();
}

bool bool_field(const json& v, const char* key) {
  if (!v.is_boolean()) throw bad("field-type", std::string("'") + key + "' must be true or false");
  return v.get<bool>();
}

// An espeak-ng language code as `espeak-ng --voices` lists it: 1..16 of a-z 0-9 - (en-us, cmn, en-gb-x-rp).
bool valid_language_code(std::string_view code) {
  if (code.empty() || code.size() > 16) return false;
  for (const char c : code)
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-')) return false;
  return true;
}

}  // namespace

std::vector<std::size_t> sentence_offsets(const SayRequest& request, std::size_t max_bytes) {
  if (request.text.find_first_not_of(" \t\r\n") == std::string::npos) return {};
  if (request.ssml) return {0};
  // A piece that is only white space (a run of it longer than the piece size) would give the
  // synthesiser nothing to say: it is dropped, its white space left on the piece before it.
  const std::vector<std::size_t> all = chunk_offsets(request.text, max_bytes);
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < all.size(); ++i) {
    const std::size_t end = i + 1 < all.size() ? all[i + 1] : request.text.size();
    const std::string_view piece = std::string_view(request.text).substr(all[i], end - all[i]);
    if (piece.find_first_not_of(" \t\r\n") != std::string_view::npos) kept.push_back(all[i]);
  }
  return kept;
}

bool valid_name(std::string_view name) {
  if (name.empty() || name.size() > 32) return false;
  for (const char c : name)
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_')) return false;
  return true;
}

SayRequest parse_say_request(std::string_view body, const SayLimits& limits) {
  json j;
  try {
    // The callback sees every value with its depth; a body nested deeper than any request is
    // refused while parsing, before a deep tree is built.
    j = json::parse(body.begin(), body.end(), [](int depth, json::parse_event_t, json&) {
      if (depth > kMaxDepth) throw bad("json-too-deep", "nesting deeper than " + std::to_string(kMaxDepth));
      return true;
    });
  } catch (const json::parse_error& e) {
    throw bad("json-malformed", "byte " + std::to_string(e.byte == 0 ? 0 : e.byte - 1) + ": " +
                                    std::string(e.what()).substr(std::string(e.what()).find(':') + 2));
  } catch (const json::out_of_range& e) {
    // A number beyond double's range ("1e999"): nlohmann reports it without a position.
    throw bad("json-malformed", std::string(e.what()).substr(std::string(e.what()).find(']') + 2));
  }
  if (!j.is_object()) throw bad("json-not-object", "the body must be a JSON object");
  SayRequest r;
  bool have_text = false;
  for (const auto& [key, v] : j.items()) {
    if (key == "text" || key == "ssml") {
      if (have_text) throw bad("text-twice", "give 'text' or 'ssml', not both");
      r.text = string_field(v, key.c_str());
      r.ssml = key == "ssml";
      have_text = true;
    } else if (key == "lang") {
      r.lang = string_field(v, "lang");
      if (!valid_language_code(r.lang))
        throw bad("lang-invalid", "'" + r.lang.substr(0, 64) + "': a language code is 1..16 of a-z 0-9 - (espeak-ng --voices)");
    } else if (key == "expression") {
      try {
        r.expression = parse_expression_blend(string_field(v, "expression"));
      } catch (const std::invalid_argument& e) {
        throw bad("expression-invalid", e.what());
      }
    } else if (key == "voice") {
      r.voice = string_field(v, "voice");
      if (!valid_name(r.voice)) throw bad("voice-invalid", "a voice name is 1..32 of a-z 0-9 - _");
    } else if (key == "rtp") {
      std::vector<std::string> urls;
      if (v.is_string()) {
        urls.push_back(v.get<std::string>());
      } else if (v.is_array()) {
        for (const json& u : v) urls.push_back(string_field(u, "rtp[]"));
      } else {
        throw bad("field-type", "'rtp' must be a udp:// URL or an array of them");
      }
      if (urls.size() > limits.max_rtp_destinations)
        throw bad("rtp-too-many", std::to_string(urls.size()) + " destinations; at most " +
                                      std::to_string(limits.max_rtp_destinations));
      for (const std::string& u : urls) {
        UdpUrl url;
        if (parse_udp_url(u, url) || url.port == 0 || url.port > 65532)
          throw bad("rtp-url", "'" + u.substr(0, 200) + "': expected udp://HOST:PORT with PORT 1..65532 (P..P+3 are used)");
        r.rtp.push_back(std::move(url));
      }
    } else if (key == "srtp") {
      r.srtp = bool_field(v, "srtp");
    } else if (key == "channel") {
      r.channel = string_field(v, "channel");
      if (!valid_name(r.channel)) throw bad("channel-invalid", "a channel is 1..32 of a-z 0-9 - _");
    } else if (key == "interrupt") {
      r.interrupt = bool_field(v, "interrupt");
    } else {
      throw bad("unknown-field", "'" + key.substr(0, 64) + "' (spec/serve.md lists the fields)");
    }
  }
  if (!have_text) throw bad("text-missing", "the body needs 'text' (or 'ssml')");
  if (r.text.size() > limits.max_text_bytes)
    throw RequestError(413, "text-too-long", std::to_string(r.text.size()) + " bytes; at most " +
                                                 std::to_string(limits.max_text_bytes) + " per request");
  try {
    (void)validate_text(r.text);
  } catch (const InputError& e) {
    throw bad("text-invalid", e.what());
  }
  if (sentence_offsets(r).empty()) throw bad("text-empty", "'text' holds nothing to say");
  if (r.srtp.value_or(false) && r.rtp.empty()) throw bad("srtp-without-rtp", "'srtp' without 'rtp': nothing to protect");
  return r;
}

}  // namespace fapcast
