#include "fapcast/recognise/speech_alignment.hpp"

#include <string>

#include "fapcast/corpus/label_tier.hpp"

namespace fapcast {

std::vector<TimedPhone> timed_phones(const SpeechAlignment& a) {
  std::vector<TimedPhone> out;
  for (const auto& s : a.segments) {
    const Phone p = s.kind == SpeechSegmentKind::phone ? s.phone : Phone::SIL;
    if (!out.empty() && p == Phone::SIL && out.back().phone == Phone::SIL) {
      out.back().end_sample = s.end_sample;
      continue;
    }
    out.push_back({p, s.start_sample, s.end_sample});
  }
  return out;
}

namespace {

std::string phone_label(const SpeechSegment& s) {
  switch (s.kind) {
    case SpeechSegmentKind::phone: return std::string(arpabet(s.phone));
    case SpeechSegmentKind::noise: return "spn";
    case SpeechSegmentKind::unmatched: return "unk";
    case SpeechSegmentKind::silence: break;
  }
  return "";
}

}  // namespace

Alignment to_alignment(const SpeechAlignment& a) {
  const double rate = static_cast<double>(a.sample_rate.hz);
  const double end = static_cast<double>(a.samples) / rate;
  Alignment out;
  out.start_s = 0;
  out.end_s = end;
  LabelTier phones{"phones", TierKind::intervals, 0, end, {}, {}};
  for (const auto& s : a.segments)
    if (s.end_sample > s.start_sample)
      phones.intervals.push_back({static_cast<double>(s.start_sample) / rate, static_cast<double>(s.end_sample) / rate, phone_label(s)});
  LabelTier words{"words", TierKind::intervals, 0, end, {}, {}};
  double at = 0;
  for (const auto& w : a.words) {
    const double ws = static_cast<double>(w.start_sample) / rate, we = static_cast<double>(w.end_sample) / rate;
    if (we <= ws) continue;
    if (ws > at) words.intervals.push_back({at, ws, ""});
    words.intervals.push_back({ws, we, w.text});
    at = we;
  }
  if (at < end) words.intervals.push_back({at, end, ""});
  out.tiers.push_back(std::move(phones));
  out.tiers.push_back(std::move(words));
  return out;
}

}  // namespace fapcast
