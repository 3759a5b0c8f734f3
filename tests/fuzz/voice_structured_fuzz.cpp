// libFuzzer target for voice files at real size, with a structure-aware mutator: an input that
// reads as a voice container is taken apart into its sections, one section is changed (its bytes
// mutated in place, a JSON section's text grown or cut, its shape changed, or the section dropped)
// and the file laid out again by VoiceFileWriter, so header, table, alignment and every CRC stay
// valid and the mutation reaches the section checks of Voice::open instead of the checksum. An
// input that does not read is mutated as bytes. Seeds: the tiny voices of voice_open_fuzz here;
// tools/run-fuzz.sh adds the reference voice (about 15 MB) when the default voice exists.
// Property: any bytes are refused with an InputError or give a voice whose parts can all be read.
#include "fapcast/core/input_error.hpp"
#include "fuzz/support/read_voice.hpp"
#include "fapcast/voice/voice_file.hpp"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <random>
#include <stdexcept>
#include <vector>

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);

namespace {
using namespace fapcast;

// The input copied to 8-byte alignment (a mapping is page-aligned; mimic it).
std::vector<std::uint64_t> aligned_copy(const std::uint8_t* data, std::size_t size) {
  std::vector<std::uint64_t> aligned(size / 8 + 1);
  if (size > 0) std::memcpy(aligned.data(), data, size);
  return aligned;
}

std::span<const std::byte> as_bytes(const std::vector<std::uint64_t>& aligned, std::size_t size) {
  return {reinterpret_cast<const std::byte*>(aligned.data()), size};
}

}  // namespace

extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t max_size,
                                               unsigned int seed) {
  std::mt19937 rng(seed);
  const auto aligned = aligned_copy(data, size);
  std::string out;
  try {
    const VoiceFileView view = VoiceFileView::over_bytes(as_bytes(aligned, size), "<mutator>");
    const auto& sections = view.sections();
    if (sections.empty()) return LLVMFuzzerMutate(data, size, max_size);
    const std::size_t pick = rng() % sections.size();
    const unsigned how = rng() % 8;  // 0-4 bytes in place, 5 JSON/bytes length, 6 shape, 7 drop
    VoiceFileWriter writer;
    for (std::size_t i = 0; i < sections.size(); ++i) {
      SectionInfo s = sections[i];
      const auto src = view.bytes(s.id);
      std::vector<std::byte> bytes(src.begin(), src.end());
      if (i == pick) {
        if (how == 7) continue;
        const std::size_t element = element_size(s.type);
        if (how <= 4 && !bytes.empty()) {
          LLVMFuzzerMutate(reinterpret_cast<std::uint8_t*>(bytes.data()), bytes.size(), bytes.size());
        } else if (how == 5 && element == 1) {
          const std::size_t room = bytes.size() + 64;
          bytes.resize(room);
          bytes.resize(LLVMFuzzerMutate(reinterpret_cast<std::uint8_t*>(bytes.data()), room - 64, room));
          s.rows = 1;
          s.cols = bytes.size();
        } else if (element > 0) {  // another shape: rows or cols one more or less, or swapped
          switch (rng() % 3) {
            case 0: std::swap(s.rows, s.cols); break;
            case 1: s.rows += 1; break;
            default: s.rows = s.rows > 0 ? s.rows - 1 : 0; break;
          }
          bytes.resize(s.rows * s.cols * element);
        }
      }
      writer.add(s.id, s.type, s.rows, s.cols, bytes);
    }
    out = writer.bytes();
  } catch (const InputError&) {  // not a voice container: mutate its bytes
    return LLVMFuzzerMutate(data, size, max_size);
  } catch (const std::invalid_argument&) {  // a layout the writer refuses
    return LLVMFuzzerMutate(data, size, max_size);
  }
  if (out.size() > max_size) return LLVMFuzzerMutate(data, size, max_size);
  std::memcpy(data, out.data(), out.size());
  return out.size();
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fapcast::fuzz::read_every_part_of_voice(data, size);
  return 0;
}
