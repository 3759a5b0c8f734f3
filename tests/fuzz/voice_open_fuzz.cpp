// libFuzzer target for Voice::open's checks beyond the container (voice_file_fuzz covers those):
// feature points (FPNT), phone graph (GRPH), RBF scalars, face maps (FMAP) ... Any bytes must be
// refused with an InputError or give a voice whose parts can all be read. Seeds: small voices
// that pass the container checks, so mutations reach the section checks.
#include "fuzz/support/read_voice.hpp"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fapcast::fuzz::read_every_part_of_voice(data, size);
  return 0;
}
