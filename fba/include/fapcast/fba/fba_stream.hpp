#pragma once
// Frame-at-a-time FBA coding for live transport: each frame becomes one byte-aligned, self-
// delimiting access unit (a plane start code, one object plane, alignment), so that RTP can carry
// one per packet and a receiver that lost packets resumes at the next intra access unit.
// spec/fba.md defines the bits. The whole-file coder shares the coder state and the plane coding
// but packs P planes without start codes (spec/fba.md §1).
#include "fapcast/codec/fap_frame.hpp"
#include "fapcast/fba/fba_errc.hpp"

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <system_error>
#include <vector>

namespace fapcast {

struct FbaCodingState;  // private: fba/src/fba_coding_state.hpp (white-box tests include it)

struct FbaEncoderOptions {
  int fap_quant = 1;      // 0 (lossless) .. 31; quantiser step = QP[fap] * fap_quant
  int intra_period = 25;  // an intra frame at least every this many frames (>= 1)
  // Whole files only: choose each FAP's P predictor per intra period (spec/fba.md §6); false
  // predicts every P value from the previous one, as the notes' codec does.
  bool choose_predictors = true;
};

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
  // Bits of the last access unit before byte alignment, start code and stuffing included.
  std::uint64_t last_bits() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

class FbaFrameDecoder {
 public:
  FbaFrameDecoder();
  ~FbaFrameDecoder();
  FbaFrameDecoder(FbaFrameDecoder&&) noexcept;
  FbaFrameDecoder& operator=(FbaFrameDecoder&&) noexcept;

  // Decodes one access unit. A predicted unit before any intra unit (or after reset()) is
  // refused with an error and decodes nothing; a corrupt unit leaves the decoder needing intra.
  std::error_code decode(std::span<const std::uint8_t> access_unit, FapFrame& out);
  // Forget the prediction state (after loss): the next decodable unit is an intra one.
  void reset();
  bool needs_intra() const;
  FrameRate rate() const;  // from the last intra unit
  // The coder state after the last unit, and the bits it consumed before byte alignment.
  const FbaCodingState& coding_state() const;
  std::uint64_t last_bits() const;
  // Frames the last unit says were skipped before it (skip_frames), 0..255.
  int last_skip_frames() const;
  // After an error: the bit offset in the unit where it was noticed.
  std::uint64_t error_bit() const;
  // The frame_number an intra unit carries (its frame index modulo 65536); -1 for a P unit.
  int last_frame_number() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace fapcast
