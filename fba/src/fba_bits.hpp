#pragma once
// Bit writing and reading for the FBA stream, with start-code emulation prevention: after 22
// consecutive 0 bits a 1 is stuffed, so 23 zeros (a start-code prefix) never occur inside a plane.
// Writer and reader mirror each other and share one bit count (raw bits, stuffing included).
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <span>
#include <system_error>
#include <vector>

namespace fapcast {

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
  explicit FbaBitReader(std::span<const std::uint8_t> bytes) : bytes_(bytes), size_bits_(8 * bytes.size()) {}

  // Reads `count` bits (0..32), most significant first. Past the end it reads zeros and sets
  // truncated; a missing stuffed bit sets stuffing_bit_missing. Errors are sticky: once set,
  // every later read returns 0.
  std::uint32_t get(int count) {
    if (count > kFastBits) return get_slow(count, false);
    const std::uint32_t v = read_bits(count, false);
    return error_ ? 0 : v;
  }
  int get_bit() { return static_cast<int>(get(1)); }
  // Reads a marker bit; a 0 sets marker_bit_missing.
  void marker();
  // Gives back the last `count` payload bits (count 0..16): ends an arithmetic segment at the
  // bits its coder actually consumed, whatever stuffing fell in the look-ahead.
  void unread(int count);
  // Checks that the plane ends here: 1 bits to the byte boundary, then nothing.
  void expect_end();
  // The same bits as get() (count 0..16), but past the end of the data reads zeros without an
  // error: the arithmetic decoder's look-ahead may run past the last plane of a unit.
  std::uint32_t lookahead_bits(int count) {
    const std::uint32_t v = read_bits(count, true);
    return error_ ? 0 : v;
  }
  int lookahead_bit() { return static_cast<int>(lookahead_bits(1)); }

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
  // The next bit without reading it (0 past the end). Stuffing is removed as soon as the 22nd
  // zero is read, so the next raw bit is the next payload bit.
  int peek_bit() const { return static_cast<int>(raw_window(pos_.raw_bits, 1)); }

 private:
  // Up to kFastBits bits at once when no stuffed bit can fall among them: fewer than 22 zeros
  // from the run so far to the window's first 1 (a window of <= 16 bits holds no 22-zero run
  // of its own). Otherwise, and in the last 3 bytes of the data, bit by bit.
  static constexpr int kFastBits = 16;
  std::uint32_t read_bits(int count, bool allow_past_end) {
    const std::uint64_t at = pos_.raw_bits;
    const std::uint64_t byte = at / 8;
    if (byte + 4 <= bytes_.size()) {  // the 32 bits from `byte` hold the window (at % 8 + count <= 23)
      const std::uint8_t* b = bytes_.data() + byte;  // one load (compilers fuse the bytes)
      const std::uint32_t u = (std::uint32_t{b[0]} << 24 | std::uint32_t{b[1]} << 16 | std::uint32_t{b[2]} << 8 | b[3])
                              << (at % 8);
      const std::uint32_t w = (u >> (31 - count)) >> 1;  // two shifts: count 0 gives 0
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
  void check_stuffed_bit(bool allow_past_end);

  std::span<const std::uint8_t> bytes_;
  std::uint64_t size_bits_;
  FbaBitPosition pos_;
  std::error_code error_;
  std::uint64_t error_bits_ = 0;
  std::uint64_t payload_bits_ = 0;
  std::uint64_t last_stuffed_ = 0;  // payload bits read when the last stuffed bit came (0: none)
};

}  // namespace fapcast
