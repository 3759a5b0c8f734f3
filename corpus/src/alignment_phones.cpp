#include "fapcast/corpus/alignment_phones.hpp"

#include "fapcast/core/input_error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace fapcast {

std::vector<TimedPhone> timed_phones(const std::vector<AlignedSegment>& segments, SampleRate sample_rate,
                                     const std::string& source, BreathAs breath) {
  const auto runs_on = static_cast<std::int64_t>(std::llround(std::max(0.0, breath.runs_on_s) * sample_rate.hz));
  std::vector<TimedPhone> out;
  out.reserve(segments.size());
  std::int64_t run_on_until = -1;  // while >= 0: the last phone is a breath that may run on to here
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const AlignedSegment& s = segments[i];
    const auto sample = [&](double seconds) {
      return alignment_sample(seconds, sample_rate, source, "segment " + std::to_string(i + 1) + " '" + s.label + "'");
    };
    TimedPhone p{s.kind == LabelKind::breath ? breath.phone : s.phone, sample(s.start_s), sample(s.end_s)};
    if (s.kind == LabelKind::silence && run_on_until >= 0 && p.start_sample == out.back().end_sample) {
      // The pause after an inhalation: the breath takes it up to run_on_until.
      out.back().end_sample = std::max(out.back().end_sample, std::min(p.end_sample, run_on_until));
      p.start_sample = out.back().end_sample;
      if (p.start_sample >= p.end_sample) continue;  // taken whole; the breath may run on further
    }
    constexpr std::int64_t kLast = std::numeric_limits<std::int64_t>::max();
    run_on_until = s.kind != LabelKind::breath || runs_on == 0 ? -1
                   : p.end_sample > kLast - runs_on        ? kLast
                                                            : p.end_sample + runs_on;
    out.push_back(p);
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
