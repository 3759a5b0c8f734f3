// libFuzzer: any bytes through the format detection and every alignment reader. The first byte
// picks the file name's extension and the options, so that each reader is reached.
#include "fapcast/corpus/alignment_file.hpp"
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
    (void)fapcast::read_alignment_file(bytes, kNames[pick & 7], o);
  } catch (const fapcast::InputError&) {
  }
  return 0;
}
