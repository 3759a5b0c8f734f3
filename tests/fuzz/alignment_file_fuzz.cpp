// libFuzzer: any bytes through the format detection and every alignment reader. The first byte
// picks the file name's extension and the options, so that each reader is reached. What is read
// becomes timed phones both ways (a breath as a pause, and as an inhalation run on over the pause
// after it): the run-on must keep the span and never make a phone end before it starts.
#include "fapcast/corpus/alignment_file.hpp"
#include "fapcast/corpus/alignment_phones.hpp"
#include "fapcast/core/input_error.hpp"
#include <cstdint>
#include <string>
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const char* kNames[] = {"a.TextGrid", "a.lab", "a.phn", "a.mlf", "a.par", "a.json", "a.txt", "a.wrd"};
  const std::uint8_t pick = data[0];
  fapcast::AlignmentFileOptions o;
  if (pick & 0x08) o.sample_rate = fapcast::SampleRate{16000};
  if (pick & 0x10) o.audio_seconds = 3.0;
  if (pick & 0x20) o.tier = "phones";
  const std::string bytes(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    const fapcast::AlignmentFile file = fapcast::read_alignment_file(bytes, kNames[pick & 7], o);
    const fapcast::SampleRate rate{16000};
    const auto paused = fapcast::timed_phones(file.segments, rate, "a");
    const auto animated = fapcast::timed_phones(file.segments, rate, "a", fapcast::kInhalation);
    if (animated.size() > paused.size()) __builtin_trap();
    if (!paused.empty() && (animated.empty() || animated.front().start_sample != paused.front().start_sample ||
                            animated.back().end_sample != paused.back().end_sample))
      __builtin_trap();
    bool ordered = true;  // what the readers give: phones that do not end before they start
    for (const auto& p : paused) ordered = ordered && p.end_sample >= p.start_sample;
    for (const auto& p : animated)
      if (ordered && p.end_sample < p.start_sample) __builtin_trap();
  } catch (const fapcast::InputError&) {
  }
  return 0;
}
