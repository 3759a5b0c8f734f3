// libFuzzer target: the whole-file FBA decoder (either profile) and the frame-at-a-time decoder
// (both profiles) on any bytes. Properties checked: no crash, no error-free report with frames
// missing, the report's counts add up to the frames returned, and a clean decode re-encodes
// losslessly (the fapcast profile at fap_quant 0, which codes every value) to the same frames.
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
  if (r.ok() && !result.sequence.frames.empty() && result.sequence.frames.size() <= 2000) {
    FbaEncoderOptions o;
    o.profile = FbaProfile::kFapcast;
    o.fap_quant = 0;
    o.intra_period = 25;
    try {
      const auto again = decode_fba(encode_fba(result.sequence, o));
      if (!again.report.ok() || !(again.sequence.frames == result.sequence.frames)) std::abort();
    } catch (const FbaEncodeError&) {
      // A blend or intensity on a coarser grid than fap_quant 0 reaches (65 at fap_quant 5), or a
      // select taken out of range by P planes: the encoder refuses it.
    }
  }
  for (const FbaProfile p : {FbaProfile::kStandard, FbaProfile::kFapcast}) {
    FbaFrameDecoder decoder(p);
    FapFrame frame;
    (void)decoder.decode(bytes, frame);
  }
  return 0;
}
