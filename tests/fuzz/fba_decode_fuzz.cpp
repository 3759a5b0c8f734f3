// libFuzzer target: the whole-file FBA decoder and the frame-at-a-time decoder on any bytes.
// Properties checked: no crash, no error-free report with frames missing, the report's counts
// add up to the frames returned.
#include "fapcast/fba/fba_file.hpp"
#include "fapcast/fba/fba_stream.hpp"

#include <cstdint>
#include <cstdlib>
#include <span>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapcast;
  const std::span<const std::uint8_t> bytes(data, size);
  const FbaDecodeResult result = decode_fba(bytes);
  const auto& r = result.report;
  if (result.sequence.frames.size() != r.frames_decoded + r.frames_lost + r.frames_skipped) std::abort();
  if (r.errors.size() > FbaDecodeReport::kMaxReportedErrors) std::abort();
  // Re-encoding what was decoded (lossless) and decoding again gives the same frames back.
  if (r.ok() && !result.sequence.frames.empty()) {
    try {
      const auto again = decode_fba(encode_fba(result.sequence, {0, 25}));
      if (!again.report.ok() || !(again.sequence.frames == result.sequence.frames)) std::abort();
    } catch (const FbaEncodeError&) {
      // A decoded value may lie beyond +/-1860 (P planes add up); the encoder refuses it.
    }
  }
  FbaFrameDecoder decoder;
  FapFrame frame;
  (void)decoder.decode(bytes, frame);
  return 0;
}
