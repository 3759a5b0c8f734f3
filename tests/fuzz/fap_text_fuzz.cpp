// libFuzzer target for the .fap text reader: any input is either refused with an InputError or
// accepted; an accepted input must round-trip through both writers (read, write, read gives the
// same frames) and the strict writer must be a fixed point. Anything else aborts.
#include "fapcast/codec/fap_text.hpp"
#include "fapcast/core/input_error.hpp"

#include <cstdint>
#include <cstdlib>
#include <string_view>

using namespace fapcast;

namespace {
void check(bool ok) {
  if (!ok) std::abort();
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  FapTextRead first;
  try {
    first = read_fap_text(bytes, "fuzz.fap");
  } catch (const InputError&) {
    return 0;  // refused with file, line and rule: fine
  }
  check(first.info.warnings.size() <= kFapTextMaxWarnings + 1);
  check(first.sequence.frames.size() <= first.info.header_frame_count);

  const std::string strict = write_fap_text(first.sequence);
  const FapTextRead again = read_fap_text(strict, "strict.fap");  // must not throw
  check(again.sequence.frames == first.sequence.frames);
  check(again.sequence.rate == first.sequence.rate);
  check(again.sequence.name == fap_text_name(first.sequence.name));
  check(again.info.warning_count == 0);
  check(write_fap_text(again.sequence) == strict);

  const FapTextRead from69 = read_fap_text(write_fap_text(first.sequence, FapTextDialect::kMask69), "69.fap");
  check(from69.sequence.frames.size() == first.sequence.frames.size());
  for (std::size_t i = 0; i < first.sequence.frames.size(); ++i)
    check(from69.sequence.frames[i] == as_mask69(first.sequence.frames[i]));
  return 0;
}
