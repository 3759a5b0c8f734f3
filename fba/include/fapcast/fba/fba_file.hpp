#pragma once
// Whole .fba files: the object start code, runs (a plane start code, an intra plane and the P
// planes up to the next intra plane, bit-packed, then byte alignment), and the end code.
// spec/fba.md §1 defines the layout; access units of fba_stream.hpp back to back are a file too.
#include "fapcast/codec/fap_frame.hpp"
#include "fapcast/fba/fba_stream.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <system_error>
#include <vector>

namespace fapcast {

// Thrown by encode_fba: code() is an fba_errc (or std::errc::invalid_argument for bad options),
// what() names the frame and FAP.
class FbaEncodeError : public std::system_error {
 public:
  using std::system_error::system_error;
};

// Encodes a whole sequence. Intra planes come every options.intra_period frames, and earlier
// when the mask changes or a P difference leaves the widest range; each intra plane's ranges
// and predictors are chosen for the frames it heads. Throws FbaEncodeError for a value it
// cannot code.
std::vector<std::uint8_t> encode_fba(const FapSequence& seq, const FbaEncoderOptions& options);

// fapcast's archival preset (`fapcast encode --archive`): an intra plane every 20 seconds
// instead of every second: longer-lived P models and fewer intra headers make files markedly
// smaller (figures in spec/fba.md §9). What it costs: a decoder that enters at a start code, or resumes after corruption, waits up to 20 s for
// the next intra plane (a corrupt byte loses up to 20 s), and seeking decodes up to 20 s of frames
// (about 0.5 ms at 25 fps).
inline constexpr std::uint32_t kFbaArchiveIntraSeconds = 20;
// The archival options for a sequence at `rate`: intra period kFbaArchiveIntraSeconds of frames
// (at least 1), predictors chosen.
FbaEncoderOptions fba_archive_options(int fap_quant, FrameRate rate);

// One refusal met while decoding: where (byte offset in the file) and why.
struct FbaDecodeError {
  std::uint64_t byte_offset = 0;
  std::error_code code;
  std::string message() const;  // "byte 1234: truncated: the bits end before the plane does"
};

struct FbaDecodeReport {
  std::uint64_t frames_decoded = 0;
  std::uint64_t frames_lost = 0;     // corrupt planes, and P planes refused until the next intra
  std::uint64_t frames_skipped = 0;  // skip_frames the stream asked for (held frames)
  std::vector<FbaDecodeError> errors;  // at most kMaxReportedErrors; errors_total counts all
  std::uint64_t errors_total = 0;
  std::uint64_t bytes = 0;
  bool ok() const { return errors_total == 0; }
  static constexpr std::size_t kMaxReportedErrors = 64;
};

struct FbaDecodeResult {
  FapSequence sequence;  // lost and skipped frames hold the frame before them (an empty frame at the start)
  FbaDecodeReport report;
};

// Decodes a whole file, never trusting it: a corrupt run is lost whole; decoding resumes at the
// next start code, and the next intra plane's frame_number says how many frames were lost.
// Never throws for a bad stream.
FbaDecodeResult decode_fba(std::span<const std::uint8_t> bytes);

}  // namespace fapcast
