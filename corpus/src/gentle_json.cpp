#include "fapcast/corpus/gentle_json.hpp"

#include "fapcast/core/input_error.hpp"
#include "fapcast/core/text_input.hpp"
#include "segment_rows.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace fapcast {

GentleRead read_gentle(std::string_view bytes, const std::string& source) {
  constexpr int kMaxDepth = 16;
  bool too_deep = false;
  const nlohmann::json::parser_callback_t limit = [&](int depth, nlohmann::json::parse_event_t, nlohmann::json&) {
    if (depth > kMaxDepth) too_deep = true;
    return !too_deep;
  };
  const nlohmann::json j = nlohmann::json::parse(bytes.begin(), bytes.end(), limit, /*allow_exceptions=*/false);
  auto fail = [&](const std::string& rule, const std::string& detail) -> void {
    throw InputError({source, std::nullopt, std::nullopt}, rule, detail);
  };
  if (too_deep) fail("gentle-json", "nested deeper than " + std::to_string(kMaxDepth) + " levels");
  if (j.is_discarded()) fail("gentle-json", "not valid JSON");
  if (!j.is_object() || !j.contains("words") || !j["words"].is_array()) {
    fail("gentle-schema", "no \"words\" array (Gentle's output has \"transcript\" and \"words\")");
  }
  GentleRead out;
  LabelTier words, phones;
  words.name = "words";
  phones.name = "phones";
  std::size_t n = 0;
  for (const nlohmann::json& w : j["words"]) {
    ++n;
    const std::string which = "word " + std::to_string(n);
    if (!w.is_object() || !w.contains("case") || !w["case"].is_string()) fail("gentle-schema", which + " has no \"case\"");
    if (w["case"] != "success") {
      ++out.untimed_words;
      continue;
    }
    const auto num = [&](const nlohmann::json& o, const char* key, const std::string& what) {
      if (!o.contains(key) || !o[key].is_number()) fail("gentle-schema", what + " has no number \"" + key + "\"");
      const double v = o[key].get<double>();
      if (!std::isfinite(v) || v < 0) fail("gentle-schema", what + "'s \"" + key + "\" is not a time");
      return v;
    };
    const double start = num(w, "start", which), end = num(w, "end", which);
    const std::string text = w.contains("word") && w["word"].is_string() ? w["word"].get<std::string>() : "";
    if (end < start) fail("gentle-order", which + " (\"" + excerpt(text) + "\") ends before it starts");
    if (!words.intervals.empty() && start < words.intervals.back().end_s - 1e-9) {
      fail("gentle-order", which + " (\"" + excerpt(text) + "\") starts before the previous word ends");
    }
    words.intervals.push_back({start, end, text});
    if (!w.contains("phones") || !w["phones"].is_array()) fail("gentle-schema", which + " has no \"phones\" array");
    double t = start;
    std::size_t k = 0;
    for (const nlohmann::json& p : w["phones"]) {
      ++k;
      const std::string what = which + " phone " + std::to_string(k);
      if (!p.is_object() || !p.contains("phone") || !p["phone"].is_string()) fail("gentle-schema", what + " has no \"phone\"");
      const double d = num(p, "duration", what);
      phones.intervals.push_back({t, t + d, p["phone"].get<std::string>()});
      t += d;
    }
    // Gentle rounds start, end and durations to 10 ms: the phones may miss the word's end by that;
    // the last phone is made to end with its word.
    if (std::abs(t - end) > 0.0151) {
      fail("gentle-order", which + " (\"" + excerpt(text) + "\"): its phones last " + detail::time_text(t - start) + " s, the word " + detail::time_text(end - start) + " s");
    }
    if (k > 0) phones.intervals.back().end_s = std::max(end, phones.intervals.back().start_s);
    if (words.intervals.size() > detail::kMaxSegments || phones.intervals.size() > detail::kMaxSegments) {
      fail("gentle-limits", "more than " + std::to_string(detail::kMaxSegments) + " words or phones");
    }
  }
  detail::close_segment_tier(words);
  detail::close_segment_tier(phones);
  const double end = std::max(words.end_s, phones.end_s);
  words.end_s = phones.end_s = end;
  out.alignment.start_s = 0;
  out.alignment.end_s = end;
  out.alignment.tiers.push_back(std::move(words));
  out.alignment.tiers.push_back(std::move(phones));
  return out;
}

}  // namespace fapcast
