#pragma once
// Bit writing and reading for the FBA stream, with start-code emulation prevention: after 22
// consecutive 0 bits a 1 is stuffed, so 23 zeros (a start-code prefix) never occur inside a plane.
// Writer and reader mirror each other and share one bit count (raw bits, stuffing included).
#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <system_error>
#include <vector>

namespace fapcast::codec {

inline constexpr std::uint32_t kFbaObjectStartCode = 0x000001BA;  // face/body object
inline constexpr std::uint32_t kFbaPlaneStartCode = 0x000001BB;   // object plane (one frame)
inline constexpr std::uint32_t kFbaEndCode = 0x000001B1;          // end of stream
inline constexpr int kStuffAfterZeros = 22;                       // a 1 follows 22 zeros

// Where a writer or reader stands: raw bits (stuffing included) and the current run of zeros.
struct FbaBitPosition {
  std::uint64_t raw_bits = 0;
  int zero_run = 0;
  bool operator==(const FbaBitPosition&) const = default;
};

// The one bit count both sides report: raw bits since the plane start, stuffing included.
inline std::uint64_t fba_bit_count(const FbaBitPosition& p) { return p.raw_bits; }

class FbaBitWriter {
 public:
  // Appends a 32-bit start code, byte-aligned (the writer must be aligned), and resets stuffing.
  void start_code(std::uint32_t code);
  // Writes the low `count` bits of `value`, most significant first; count 0..32.
  void put(std::uint32_t value, int count);
  void put_bit(int bit);
  // Pads with 1 bits to the next byte boundary (never a 0, so no start code is emulated).
  void align();
  const FbaBitPosition& position() const { return pos_; }
  std::vector<std::uint8_t>& bytes() { return bytes_; }

 private:
  void raw_bit(int bit);
  std::vector<std::uint8_t> bytes_;
  FbaBitPosition pos_;
};

class FbaBitReader {
 public:
  explicit FbaBitReader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

  // Reads `count` bits (0..32), most significant first. Past the end it reads zeros and sets
  // truncated; a missing stuffed bit sets stuffing_bit_missing. Errors are sticky: once set,
  // every later read returns 0.
  std::uint32_t get(int count);
  int get_bit() {
    const int bit = payload_bit(false);
    return error_ ? 0 : bit;
  }
  // Reads a marker bit; a 0 sets marker_bit_missing.
  void marker();
  // Gives back the last `count` payload bits (count 0..16): ends an arithmetic segment at the
  // bits its coder actually consumed, whatever stuffing fell in the look-ahead.
  void unread(int count);
  // Checks that the plane ends here: 1 bits to the byte boundary, then nothing.
  void expect_end();
  // The same bits as get(), but past the end of the data reads zeros without an error: the
  // arithmetic decoder's 16-bit look-ahead may run past the last plane of a unit.
  int lookahead_bit() {
    const int bit = payload_bit(true);
    return error_ ? 0 : bit;
  }

  const FbaBitPosition& position() const { return pos_; }
  std::error_code error() const { return error_; }
  void fail(std::error_code e) {
    if (error_) return;
    error_ = e;
    error_bits_ = std::min<std::uint64_t>(pos_.raw_bits, 8 * bytes_.size());
  }
  // Where the first error was noticed: raw bits from the start, at most the data's length.
  std::uint64_t error_bits() const { return error_bits_; }
  bool past_end() const { return pos_.raw_bits > 8 * bytes_.size(); }
  bool at_end() const { return pos_.raw_bits == 8 * bytes_.size(); }
  // The next bit without reading it (0 past the end). Stuffing is removed as soon as the 22nd
  // zero is read, so the next raw bit is the next payload bit.
  int peek_bit() const {
    const std::uint64_t at = pos_.raw_bits;
    return at < 8 * bytes_.size() ? (bytes_[at / 8] >> (7 - at % 8)) & 1 : 0;
  }

 private:
  // Inline: the decoder's hot path is one call per bit.
  int raw_bit(bool allow_past_end) {
    const std::uint64_t at = pos_.raw_bits++;
    if (at >= 8 * bytes_.size()) {
      if (!allow_past_end) fail_truncated();
      return 0;
    }
    return (bytes_[at / 8] >> (7 - at % 8)) & 1;
  }
  int payload_bit(bool allow_past_end) {
    history_[payload_bits_++ % history_.size()] = pos_;
    const int bit = raw_bit(allow_past_end);
    if (bit) {
      pos_.zero_run = 0;
    } else if (++pos_.zero_run == kStuffAfterZeros) {
      check_stuffed_bit(allow_past_end);
    }
    return bit;
  }
  void fail_truncated();
  void check_stuffed_bit(bool allow_past_end);
  std::span<const std::uint8_t> bytes_;
  FbaBitPosition pos_;
  std::error_code error_;
  std::uint64_t error_bits_ = 0;
  std::array<FbaBitPosition, 16> history_{};  // where each of the last 16 payload bits began
  std::uint32_t payload_bits_ = 0;
};

}  // namespace fapcast::codec
