// libFuzzer target for the voice file reader: any bytes must be refused with an InputError or
// accepted as a voice whose every section can be read in place without going out of bounds.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "fapcast/core/input_error.hpp"
#include "fapcast/voice/voice_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapcast;
  std::vector<std::uint64_t> aligned(size / 8 + 1);  // a mapping is page-aligned; mimic it
  if (size > 0) std::memcpy(aligned.data(), data, size);
  try {
    const VoiceFileView view = VoiceFileView::over_bytes(
        {reinterpret_cast<const std::byte*>(aligned.data()), size}, "<fuzz>");
    double sum = 0;
    for (const SectionInfo& s : view.sections()) {
      for (const std::byte b : view.bytes(s.id)) sum += static_cast<double>(b);
      if (s.type == ElementType::kFloat32) sum += static_cast<double>(view.matrix_f32(s.id).sum());
      if (s.type == ElementType::kFloat64) sum += view.matrix_f64(s.id).sum();
    }
    check_voice_sections(view);
    (void)view.provenance();
    (void)sum;
  } catch (const InputError&) {
  }
  return 0;
}
