#pragma once
// Whole .fba files in either profile (spec/fba.md §1, §9). Standard: the object start code,
// planes (a plane start code before each intra period, P planes packed after it), the end code.
// fapcast profile: the same inside, opened by user data "fapcast" instead of the object start
// code, so that a standard decoder refuses it at its first bytes. Access units of fba_stream.hpp
// back to back after the opening are a file too.
#include "fapcast/codec/fap_frame.hpp"
#include "fapcast/fba/fba_profile.hpp"
#include "fapcast/fba/fba_stream.hpp"

#include <cstdint>
#include <optional>
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

struct FbaEncodeStats {
  std::uint64_t intra_planes = 0;
  std::uint64_t predicted_planes = 0;
  // Standard: frames coded as intra planes (or with a widened range field) so that every standard
  // decoder, the published one included, reads them alike (spec/fba.md §2), and frames no coding
  // of which does (their FAP 1/2 fields decide it): coded for the reference reading.
  std::uint64_t recoded_for_decoders = 0;
  std::uint64_t not_read_alike = 0;
  std::uint64_t state_checksum = 0;  // the coder state after the last plane (decode_fba's report has it too)
};

// Encodes a whole sequence. Intra planes come every options.intra_period frames, and earlier
// when the mask changes or (standard) a P difference leaves the widest range; each intra plane's
// ranges (standard) or predictors, references and alphabets (fapcast) are chosen for the frames
// it heads. Throws FbaEncodeError for a value it cannot code.
std::vector<std::uint8_t> encode_fba(const FapSequence& seq, const FbaEncoderOptions& options,
                                     FbaEncodeStats* stats = nullptr);

// Where the standard syntax cannot code `seq` at `fap_quant` (a value beyond its widest range,
// spec/fba.md §6): the first refusal, naming frame and FAP; nullopt when it can.
std::optional<std::string> fba_standard_refusal(const FapSequence& seq, int fap_quant);

// fapcast's archival preset (`fapcast encode --archive`): an intra plane every 20 seconds.
// What it costs: a decoder that resumes after corruption waits up to 20 s for the next intra
// plane, and seeking decodes up to 20 s of frames.
inline constexpr std::uint32_t kFbaArchiveIntraSeconds = 20;
FbaEncoderOptions fba_archive_options(FbaProfile profile, int fap_quant, FrameRate rate);

// The bytes that open a fapcast-profile file: user_data_start_code, "fapcast", version 1.
inline constexpr std::uint8_t kFbaFapcastVersion = 1;
std::span<const std::uint8_t> fba_fapcast_opening();
// The profile a file's first bytes announce (nullopt: neither opening).
std::optional<FbaProfile> fba_file_profile(std::span<const std::uint8_t> bytes);

// One refusal met while decoding: where (byte offset in the file) and why.
struct FbaDecodeError {
  std::uint64_t byte_offset = 0;
  std::error_code code;
  std::string message() const;  // "byte 1234: truncated: the bits end before the plane does"
};

struct FbaDecodeReport {
  FbaProfile profile = FbaProfile::kStandard;
  // Standard: the stuffing reading the stream decoded under (kReference unless only the
  // continuous one decodes it: spec/fba.md §2).
  FbaStuffing stuffing = FbaStuffing::kReference;
  int fap_quant = 0;                 // of the last intra plane
  bool rate_known = false;           // false: no intra plane carried a rate (25 fps assumed)
  std::uint64_t frames_decoded = 0;
  std::uint64_t frames_lost = 0;     // corrupt planes, and P planes refused until the next intra
  std::uint64_t frames_skipped = 0;  // skip_frames the stream asked for (held frames)
  std::uint64_t time_code_mismatches = 0;  // standard: time codes off the running time by >= 1 s
  std::uint64_t state_checksum = 0;  // the coder state after the last plane (as FbaEncodeStats)
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

struct FbaDecodeOptions {
  // Only the standard syntax: a fapcast-profile file is refused (fapcast-profile) at byte 0.
  bool standard_only = false;
  // Standard: one stuffing reading only (default: the reference one, then the continuous one
  // when only it decodes the stream).
  std::optional<FbaStuffing> stuffing;
  // Standard: end segments as the published decoder does (a fixed 14 raw bits given back, a
  // seeming stuffing error in the look-ahead kept): to check that it reads a stream alike.
  bool fixed_give_back = false;
};

// Decodes a whole file, never trusting it: a corrupt run is lost whole; decoding resumes at the
// next start code; the fapcast profile's frame numbers say how many frames were lost. Never
// throws for a bad stream.
FbaDecodeResult decode_fba(std::span<const std::uint8_t> bytes, const FbaDecodeOptions& options = {});

}  // namespace fapcast
