#include "recorded_speech.hpp"

#include "command.hpp"

#include "fapcast/core/downmix.hpp"
#include "fapcast/core/file_io.hpp"
#include "fapcast/core/wav_file.hpp"
#include "fapcast/corpus/alignment_file.hpp"
#include "fapcast/corpus/alignment_phones.hpp"

#include <filesystem>
#include <iostream>

namespace fapcast::cli {
namespace {

// An alignment may end up to 20 ms after its audio (rounding, a trailing pause) and is cut there.
constexpr std::int64_t kToleranceMs = 20;

}  // namespace

void add_alignment_options(CLI::App& command, AlignmentArgs& args) {
  command.add_option("--tier", args.tier, "The alignment's phone tier (default: found by name, then by its labels)");
  command.add_option("--phone-set", args.phone_set,
                     "The labels' symbol set: arpabet, timit, ipa, sampa, emu-ae, mocha (default: the set that reads them)");
}

RecordedPhones phones_from_alignment(const std::string& wav, const std::string& alignment, const AlignmentArgs& args,
                                     const std::string& command, bool quiet) {
  AlignmentFileOptions options;
  if (!args.tier.empty()) options.tier = args.tier;
  if (!args.phone_set.empty()) {
    options.label_set = label_set_from_name(args.phone_set);
    if (!options.label_set)
      throw UsageError(command + ": --phone-set '" + args.phone_set +
                       "' is none of arpabet, timit, ipa, sampa, emu-ae, mocha");
  }
  const Audio recorded = read_wav(wav);
  const Audio audio = downmix_to_mono(recorded);
  RecordedPhones out;
  out.sample_rate = audio.sample_rate;
  out.samples = audio.instants();
  options.sample_rate = audio.sample_rate;
  options.utterance = std::filesystem::path(wav).stem().string();  // an MLF's entry
  options.audio_seconds = static_cast<double>(out.samples) / static_cast<double>(audio.sample_rate.hz);
  const AlignmentFile file = read_alignment_file(read_file(alignment), alignment, options);
  if (!quiet) {
    if (recorded.channels > 1)
      std::cerr << "fapcast: note: " << wav << ": " << recorded.channels << " channels downmixed to mono\n";
    for (const std::string& note : file.notes) std::cerr << "fapcast: note: " << alignment << ": " << note << "\n";
  }
  auto phones = timed_phones(file.segments, audio.sample_rate, alignment, kInhalation);
  if (!phones.empty() && phones.back().end_sample < out.samples && !quiet)
    std::cerr << "fapcast: warning: " << alignment << " ends before " << wav << "; the rest is animated as silence\n";
  out.phones = fit_phones_to_audio(std::move(phones), out.samples, kToleranceMs * audio.sample_rate.hz / 1000, alignment);
  return out;
}

RecordedPhones phones_from_recording(const std::string& wav, const TranscriptArgs& transcript, bool quiet) {
  const SpeechAlignment found = align_recording(wav, transcript, quiet);
  return {timed_phones(found), found.sample_rate, found.samples};
}

}  // namespace fapcast::cli
