#pragma once
// Frame-at-a-time FBA coding for live transport: each frame becomes one byte-aligned, self-
// delimiting access unit (a plane start code, one object plane, next_start_code() stuffing), so
// that RTP can carry one per packet and a receiver that lost packets resumes at the next intra
// access unit. Both profiles (spec/fba.md §1, §9): a standard unit is what the standard syntax
// allows ("a start code before every plane"); a fapcast-profile unit follows the profile's syntax
// and is told apart by the RTP payload header, not by its bits. The whole-file coder shares the
// coder state and the plane coding but packs P planes without start codes.
#include "fapcast/codec/fap_frame.hpp"
#include "fapcast/fba/fba_errc.hpp"
#include "fapcast/fba/fba_profile.hpp"

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <system_error>
#include <vector>

namespace fapcast {

struct FbaCodingState;  // private: fba/src/fba_coding_state.hpp (white-box tests include it)

struct FbaEncoderOptions {
  FbaProfile profile = FbaProfile::kStandard;
  int fap_quant = 1;      // 0 (lossless) .. 31; quantiser step = QP[fap] * fap_quant
  // An intra plane at least every this many frames (>= 1); 0 = the default: files 10 s of frames
  // (standard) or 20 s (fapcast profile), frame-at-a-time coders 1 s.
  int intra_period = 0;
  // fapcast profile: choose each FAP's temporal predictor and reference FAP per intra period
  // (spec/fba.md §10); false predicts every P value from the previous one alone.
  bool choose_predictors = true;
  // Standard: a time code in every intra plane (spec/fba.md §3).
  bool time_codes = true;
};

// The intra period `options` ask for at `rate`, in frames (>= 1).
int fba_intra_period(const FbaEncoderOptions& options, FrameRate rate, bool whole_file);

struct FbaAccessUnit {
  std::vector<std::uint8_t> bytes;  // starts with the object-plane start code, byte-aligned end
  bool intra = false;
};

class FbaFrameEncoder {
 public:
  FbaFrameEncoder(FbaEncoderOptions options, FrameRate rate);
  ~FbaFrameEncoder();
  FbaFrameEncoder(FbaFrameEncoder&&) noexcept;
  FbaFrameEncoder& operator=(FbaFrameEncoder&&) noexcept;

  // Codes the next frame. `force_intra` starts a new intra frame (a late joiner, a request).
  // Errors: a value outside the codable range (never clipped), an invalid option.
  std::error_code encode(const FapFrame& frame, FbaAccessUnit& out, bool force_intra = false);
  // After an error from encode(): which frame and FAP, and why ("frame 12, FAP 48 head_pitch: ...").
  const std::string& error_detail() const;
  // The coder state after the last frame (tests compare it with the decoder's).
  const FbaCodingState& coding_state() const;
  // Bits of the last access unit before its stuffing, start code included.
  std::uint64_t last_bits() const;
  // Standard: frames coded as intra planes although P planes were due, so that every standard
  // decoder reads them alike (spec/fba.md §2).
  std::uint64_t recoded_intra() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

class FbaFrameDecoder {
 public:
  explicit FbaFrameDecoder(FbaProfile profile = FbaProfile::kStandard);
  ~FbaFrameDecoder();
  FbaFrameDecoder(FbaFrameDecoder&&) noexcept;
  FbaFrameDecoder& operator=(FbaFrameDecoder&&) noexcept;

  // Decodes one access unit. A predicted unit before any intra unit (or after reset()) is
  // refused with an error and decodes nothing; a corrupt unit leaves the decoder needing intra.
  std::error_code decode(std::span<const std::uint8_t> access_unit, FapFrame& out);
  // Forget the prediction state (after loss): the next decodable unit is an intra one. A
  // different profile than before switches the decoder to it.
  void reset(FbaProfile profile);
  void reset() { reset(profile()); }
  FbaProfile profile() const;
  bool needs_intra() const;
  FrameRate rate() const;  // from the last intra unit
  int fap_quant() const;   // of the last intra unit
  // The coder state after the last unit, and the bits it consumed before the stuffing.
  const FbaCodingState& coding_state() const;
  std::uint64_t last_bits() const;
  // Frames the last unit says are skipped after it (skip_frames), 0..255.
  int last_skip_frames() const;
  // After an error: the bit offset in the unit where it was noticed.
  std::uint64_t error_bit() const;
  // fapcast profile: the frame_number an intra unit carries (its frame index modulo 65536); -1
  // for a P unit or a standard unit.
  int last_frame_number() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace fapcast
