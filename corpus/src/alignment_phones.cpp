#include "fapcast/corpus/alignment_phones.hpp"

#include "fapcast/core/input_error.hpp"
#include "fapcast/phonetics/phone_map.hpp"

#include <algorithm>
#include <stdexcept>

namespace fapcast {
namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

// ARPAbet first (CMUdict aligners: MFA, Gentle, the reference talker), then TIMIT/MOCHA.
TimitPhone parse_label(const std::string& label, const std::string& where) {
  if (label.empty()) return {Phone::SIL, false};
  try {
    return {parse_arpabet(label, where).phone, false};
  } catch (const std::invalid_argument&) {
  }
  try {
    return phone_from_timit(label, where);
  } catch (const std::invalid_argument&) {
  }
  throw InputError({where, {}, {}}, "phone-label",
                   "'" + label + "' is neither an ARPAbet nor a TIMIT phone label");
}

}  // namespace

const LabelTier* phone_tier(const Alignment& alignment) {
  const LabelTier* first = nullptr;
  for (const LabelTier& t : alignment.tiers) {
    if (t.kind != TierKind::intervals) continue;
    const std::string name = lower(t.name);
    if (name == "phones" || name == "phone") return &t;
    if (first == nullptr) first = &t;
  }
  return first;
}

std::vector<TimedPhone> phones_from_tier(const LabelTier& tier, SampleRate sample_rate,
                                         const std::string& source) {
  std::vector<TimedPhone> out;
  bool previous_closure = false;
  for (std::size_t i = 0; i < tier.intervals.size(); ++i) {
    const Interval& in = tier.intervals[i];
    const std::string where = source + ": tier '" + tier.name + "' interval " + std::to_string(i + 1);
    const TimitPhone p = parse_label(in.label, where);
    const auto sample = [&](double seconds) {
      try {
        return to_sample(seconds, sample_rate);
      } catch (const std::out_of_range& e) {
        throw InputError({where, {}, {}}, "time-off-sample-grid", e.what());
      }
    };
    const std::int64_t start = sample(in.start_s);
    const std::int64_t end = sample(in.end_s);
    if (previous_closure && !p.closure && out.back().phone == p.phone && out.back().end_sample == start) {
      out.back().end_sample = end;  // closure + release: one phone
    } else {
      out.push_back({p.phone, start, end});
    }
    previous_closure = p.closure;
  }
  return out;
}

std::vector<TimedPhone> fit_phones_to_audio(std::vector<TimedPhone> phones, std::int64_t audio_samples,
                                            std::int64_t tolerance_samples, const std::string& source) {
  const std::int64_t end = phones.empty() ? 0 : phones.back().end_sample;
  if (end > audio_samples + tolerance_samples)
    throw InputError({source, {}, {}}, "alignment-longer-than-audio",
                     "the phones end at sample " + std::to_string(end) + ", the audio at " +
                         std::to_string(audio_samples) + " (more than " +
                         std::to_string(tolerance_samples) + " samples apart)");
  while (!phones.empty() && phones.back().start_sample >= audio_samples) phones.pop_back();
  if (!phones.empty()) phones.back().end_sample = std::min(phones.back().end_sample, audio_samples);
  return phones;
}

}  // namespace fapcast
