#include "fapcast/corpus/alignment_phones.hpp"

#include "fapcast/core/input_error.hpp"

#include <algorithm>
#include <string>

namespace fapcast {

std::vector<TimedPhone> timed_phones(const std::vector<AlignedSegment>& segments, SampleRate sample_rate,
                                     const std::string& source, Phone breath_as) {
  std::vector<TimedPhone> out;
  out.reserve(segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const AlignedSegment& s = segments[i];
    const auto sample = [&](double seconds) {
      return alignment_sample(seconds, sample_rate, source, "segment " + std::to_string(i + 1) + " '" + s.label + "'");
    };
    out.push_back({s.kind == LabelKind::breath ? breath_as : s.phone, sample(s.start_s), sample(s.end_s)});
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
