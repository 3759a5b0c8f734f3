#include "fapcast/eval/alignment_evaluation.hpp"

#include <algorithm>
#include <cmath>

#include "fapcast/core/file_io.hpp"
#include "fapcast/core/text_input.hpp"
#include "fapcast/core/wav_file.hpp"
#include "fapcast/corpus/alignment_file.hpp"
#include "fapcast/corpus/alignment_phones.hpp"
#include "fapcast/phonetics/viseme.hpp"
#include "fapcast/recognise/speech_aligner.hpp"

namespace fapcast {

namespace {

// The phone at `sample` (the last one when past the end).
Phone phone_at(std::span<const TimedPhone> phones, std::int64_t sample) {
  const auto it = std::upper_bound(phones.begin(), phones.end(), sample,
                                   [](std::int64_t s, const TimedPhone& p) { return s < p.end_sample; });
  return it == phones.end() ? phones.back().phone : it->phone;
}

std::vector<TimedPhone> reference_phones(const ReferenceRecording& r, const Audio& audio) {
  AlignmentFileOptions options;
  options.sample_rate = audio.sample_rate;
  options.audio_seconds = static_cast<double>(audio.instants()) / static_cast<double>(audio.sample_rate.hz);
  const AlignmentFile file = read_alignment_file(read_file(r.labels), r.labels, options);
  return timed_phones(file.segments, audio.sample_rate, r.labels);
}

void add(AlignmentScore& to, const AlignmentScore& s) {
  to.recordings += s.recordings;
  to.seconds += s.seconds;
  to.boundaries.errors_s.insert(to.boundaries.errors_s.end(), s.boundaries.errors_s.begin(), s.boundaries.errors_s.end());
  to.boundaries.reference_phones += s.boundaries.reference_phones;
  to.boundaries.matched += s.boundaries.matched;
  to.boundaries.substituted += s.boundaries.substituted;
  to.boundaries.deleted += s.boundaries.deleted;
  to.frames.frames += s.frames.frames;
  to.frames.in_class += s.frames.in_class;
}

}  // namespace

FrameAgreement viseme_frame_agreement(std::span<const TimedPhone> reference, std::span<const TimedPhone> hypothesis,
                                      SampleRate sample_rate, double frame_s) {
  FrameAgreement a;
  if (reference.empty() || hypothesis.empty()) return a;
  const double rate = static_cast<double>(sample_rate.hz);
  const double start = static_cast<double>(reference.front().start_sample) / rate;
  const double end = static_cast<double>(reference.back().end_sample) / rate;
  for (std::size_t k = 0;; ++k) {
    const double t = start + (static_cast<double>(k) + 0.5) * frame_s;
    if (t >= end) break;
    const auto sample = static_cast<std::int64_t>(std::floor(t * rate));
    ++a.frames;
    a.in_class += search_viseme(phone_at(reference, sample)) == search_viseme(phone_at(hypothesis, sample));
  }
  return a;
}

std::vector<ReferenceRecording> reference_recordings(const std::string& data_dir) {
  std::vector<ReferenceRecording> out;
  const std::string emu = data_dir + "/speech/emu-ae/";
  for (const char* u : {"msajc003", "msajc010", "msajc012", "msajc015", "msajc022", "msajc023", "msajc057"})
    out.push_back({"EMU ae", u, emu + u + ".wav", emu + u + ".lab", emu + u + ".txt"});
  const std::string mocha = data_dir + "/mocha/fsew0_001";
  out.push_back({"MOCHA-TIMIT", "fsew0_001", mocha + ".wav", mocha + ".lab", mocha + ".txt"});
  const std::string arctic = data_dir + "/speech/arctic/arctic_a0009";
  out.push_back({"ARCTIC slt (HTS, machine)", "a0009", arctic + ".wav", arctic + "_phone.lab", arctic + ".txt"});
  return out;
}

std::vector<AlignmentScore> evaluate_alignment(std::span<const ReferenceRecording> recordings) {
  std::vector<AlignmentScore> out;
  SpeechAligner aligner;
  for (const ReferenceRecording& r : recordings) {
    const Audio audio = read_wav(r.wav);
    const std::vector<TimedPhone> reference = reference_phones(r, audio);
    const Transcript transcript = parse_transcript(decode_text(read_file(r.transcript), r.transcript, "transcript"), r.transcript);
    const std::vector<TimedPhone> aligned = timed_phones(aligner.align(audio, transcript, r.wav));
    const std::vector<TimedPhone> heard = timed_phones(aligner.recognise(audio, r.wav));
    AlignmentScore s;
    s.set = r.set;
    s.recordings = 1;
    s.seconds = static_cast<double>(audio.instants()) / static_cast<double>(audio.sample_rate.hz);
    s.boundaries = boundary_agreement(reference, aligned, audio.sample_rate);
    s.frames = viseme_frame_agreement(reference, heard, audio.sample_rate);
    const auto set = std::find_if(out.begin(), out.end(), [&](const AlignmentScore& o) { return o.set == r.set; });
    if (set == out.end()) out.push_back(s);
    else add(*set, s);
  }
  if (out.size() > 1) {
    AlignmentScore all;
    all.set = "all";
    for (const auto& s : out) add(all, s);
    out.push_back(all);
  }
  return out;
}

}  // namespace fapcast
