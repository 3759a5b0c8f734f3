#pragma once
// Bit writing and reading for the FBA stream, with start-code emulation prevention: a 1 is
// stuffed after 22 consecutive 0 bits, so that 23 zeros (a start-code prefix) never occur where
// the rule applies; where it applies is the stuffing reading (FbaStuffing, spec/fba.md §2).
// Writer and reader mirror each other and share one bit count (raw bits, stuffing included).
#include "fapcast/fba/fba_profile.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <span>
#include <system_error>
#include <vector>

namespace fapcast {

inline constexpr std::uint32_t kFbaObjectStartCode = 0x000001BA;  // face/body object
inline constexpr std::uint32_t kFbaPlaneStartCode = 0x000001BB;   // object plane
inline constexpr std::uint32_t kFbaEndCode = 0x000001B1;          // end of stream
inline constexpr std::uint32_t kFbaUserDataStartCode = 0x000001B2;  // user data (the fapcast profile's header)
inline constexpr int kStuffAfterZeros = 22;                       // a 1 follows 22 zeros

// Where a writer or reader stands: raw bits (stuffing included) and the current run of zeros.
struct FbaBitPosition {
  std::uint64_t raw_bits = 0;
  int zero_run = 0;
  bool operator==(const FbaBitPosition&) const = default;
};

// The one bit count both sides report: raw bits since the plane start, stuffing included.
inline std::uint64_t fba_bit_count(const FbaBitPosition& p) { return p.raw_bits; }

// Where an arithmetic-coded segment lay, in raw bits of the writer (for checks).
struct FbaSegmentSpan {
  std::uint64_t begin = 0, end = 0;
};

class FbaBitWriter {
 public:
  explicit FbaBitWriter(FbaStuffing stuffing = FbaStuffing::kReference) : stuffing_(stuffing) {}
  // Appends a 32-bit start code, byte-aligned (the writer must be aligned), and resets stuffing.
  void start_code(std::uint32_t code);
  // next_start_code(): a 0, then 1s to the next byte boundary (01111111 when already aligned).
  // Never counted or stuffed.
  void stuff_to_start_code();
  // Writes the low `count` bits of `value`, most significant first; count 0..32.
  void put(std::uint32_t value, int count);
  void put_bit(int bit);
  // Arithmetic-coded segments: kReference counts and stuffs only between these calls.
  void begin_segment();
  void end_segment();
  const FbaBitPosition& position() const { return pos_; }
  std::vector<std::uint8_t>& bytes() { return bytes_; }
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }
  FbaStuffing stuffing() const { return stuffing_; }

  // Taking a plane back: a mark before it, and a rollback to it. The trace since the last
  // mark: every segment and every stuffed bit (raw positions), for the compatibility checks.
  struct Mark {
    std::size_t bytes = 0;
    std::uint8_t last_byte = 0;
    FbaBitPosition pos;
    bool in_segment = false;
  };
  Mark mark();
  void rollback(const Mark& m);
  const std::vector<FbaSegmentSpan>& segments() const { return segments_; }
  const std::vector<std::uint64_t>& stuffed_bits() const { return stuffed_; }

 private:
  void raw_bit(int bit);
  std::vector<std::uint8_t> bytes_;
  FbaBitPosition pos_;
  FbaStuffing stuffing_;
  bool in_segment_ = false;
  std::vector<FbaSegmentSpan> segments_;
  std::vector<std::uint64_t> stuffed_;
};

class FbaBitReader {
 public:
  explicit FbaBitReader(std::span<const std::uint8_t> bytes, FbaStuffing stuffing = FbaStuffing::kReference)
      : bytes_(bytes), size_bits_(8 * bytes.size()), stuffing_(stuffing), counting_(stuffing == FbaStuffing::kContinuous) {}

  // Reads `count` bits (0..32), most significant first. Past the end it reads zeros and sets
  // truncated; a missing stuffed bit sets stuffing_bit_missing (inside a kReference segment only
  // when the encoder wrote that bit: see end_segment). Errors are sticky: once set, every later
  // read returns 0.
  std::uint32_t get(int count) {
    if (count > kFastBits) return get_slow(count, false);
    const std::uint32_t v = read_bits(count, false);
    return error_ ? 0 : v;
  }
  int get_bit() { return static_cast<int>(get(1)); }
  // Reads a marker bit; a 0 sets marker_bit_missing.
  void marker();
  // The published decoder's way of ending a segment: give back a fixed number of raw bits, and
  // take a 0 after 22 zeros in the look-ahead as a stuffing error (kReference). Only to check
  // that a stream reads alike that way (spec/fba.md §2).
  void set_fixed_give_back(bool on) { fixed_give_back_ = on; }
  // An arithmetic-coded segment starts: kReference starts counting zeros from here.
  void begin_segment();
  // The segment ends `give_back` (0..16) payload bits before the reader: it returns right after
  // the last bit the encoder wrote, whatever stuffing (real, or only apparent in the look-ahead)
  // it met in those bits. A stuffing error the reader met only in them is dropped.
  void end_segment(int give_back);
  // The same bits as get() (count 0..16), but past the end of the data reads zeros without an
  // error: the arithmetic decoder's look-ahead may run past the last plane of a unit.
  std::uint32_t lookahead_bits(int count) {
    const std::uint32_t v = read_bits(count, true);
    return error_ ? 0 : v;
  }
  int lookahead_bit() { return static_cast<int>(lookahead_bits(1)); }
  // Moves to raw bit `at` (a start code's end): zero run 0, outside any segment.
  void seek(std::uint64_t at);

  const FbaBitPosition& position() const { return pos_; }
  std::error_code error() const { return error_; }
  void fail(std::error_code e) {
    if (error_) return;
    error_ = e;
    error_bits_ = std::min<std::uint64_t>(pos_.raw_bits, size_bits_);
  }
  // Where the first error was noticed: raw bits from the start, at most the data's length.
  std::uint64_t error_bits() const { return error_bits_; }
  bool past_end() const { return pos_.raw_bits > size_bits_; }
  bool at_end() const { return pos_.raw_bits == size_bits_; }
  std::uint64_t size_bits() const { return size_bits_; }
  std::span<const std::uint8_t> data() const { return bytes_; }
  // The next raw bit without reading it (0 past the end).
  int peek_bit() const { return static_cast<int>(raw_window(pos_.raw_bits, 1)); }

 private:
  // Up to kFastBits bits at once when no stuffed bit can fall among them: not counting, or fewer
  // than 22 zeros from the run so far to the window's first 1 (a window of <= 16 bits holds no
  // 22-zero run of its own). Otherwise, and in the last 3 bytes of the data, bit by bit.
  static constexpr int kFastBits = 16;
  std::uint32_t read_bits(int count, bool allow_past_end) {
    const std::uint64_t at = pos_.raw_bits;
    const std::uint64_t byte = at / 8;
    if (byte + 4 <= bytes_.size()) {  // the 32 bits from `byte` hold the window (at % 8 + count <= 23)
      const std::uint8_t* b = bytes_.data() + byte;  // one load (compilers fuse the bytes)
      const std::uint32_t u = (std::uint32_t{b[0]} << 24 | std::uint32_t{b[1]} << 16 | std::uint32_t{b[2]} << 8 | b[3])
                              << (at % 8);
      const std::uint32_t w = (u >> (31 - count)) >> 1;  // two shifts: count 0 gives 0
      if (!counting_) {
        pos_.raw_bits = at + static_cast<std::uint64_t>(count);
        return w;
      }
      const int leading_zeros = std::min(std::countl_zero(u | 1u), count);
      if (pos_.zero_run + leading_zeros < kStuffAfterZeros) {
        pos_.raw_bits = at + static_cast<std::uint64_t>(count);
        payload_bits_ += static_cast<std::uint64_t>(count);
        // The zeros after the window's last 1, plus the run before it when the window is all 0.
        pos_.zero_run = std::countr_zero(w | (1u << count)) + (w == 0 ? pos_.zero_run : 0);
        return w;
      }
    }
    return get_slow(count, allow_past_end);
  }
  // `count` (1..kFastBits) raw bits at raw bit `at`, most significant first, zeros past the end.
  std::uint32_t raw_window(std::uint64_t at, int count) const {
    const std::uint64_t byte = at / 8;
    std::uint32_t w = 0;  // the 4 bytes from `byte`, big-endian, zeros past the end
    for (std::uint64_t i = 0; i < 4; ++i) w = (w << 8) | (byte + i < bytes_.size() ? bytes_[byte + i] : 0u);
    return (w << (at % 8)) >> (32 - count);
  }
  std::uint32_t get_slow(int count, bool allow_past_end);
  int raw_bit(bool allow_past_end);
  int payload_bit(bool allow_past_end);

  std::span<const std::uint8_t> bytes_;
  std::uint64_t size_bits_;
  FbaStuffing stuffing_;
  bool counting_;  // kContinuous, or inside a kReference segment
  bool fixed_give_back_ = false;
  FbaBitPosition pos_;
  std::error_code error_;
  std::uint64_t error_bits_ = 0;
  std::uint64_t payload_bits_ = 0;    // payload bits read while counting
  std::uint64_t last_stuffed_ = 0;    // payload_bits_ when the last stuffed bit was met (0: none)
  std::uint64_t stuffing_missing_ = 0;  // kReference: payload_bits_ at a missing stuffed bit (0: none)
  std::uint64_t stuffing_missing_raw_ = 0;
};

}  // namespace fapcast
