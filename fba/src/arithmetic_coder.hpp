#pragma once
// The adaptive arithmetic coder of the FBA stream, after H.263 Annex E: 16-bit registers
// (top 65535, quarter points 16384, 32768, 49152), cumulative-frequency tables descending with
// the total first, every model starting uniform, all counts halved before the total would pass
// 16383. A coded symbol's count grows by the model's increment: 1 in the standard syntax, a power
// of two the fapcast profile's intra header chooses (spec/fba.md). Encoder and decoder mirror each
// other over one model type. Segments start and end the bit layer's stuffing scope (fba_bits.hpp).
#include "exact_reciprocal.hpp"
#include "fba_bits.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace fapcast {

// An adaptive frequency model over the symbols 0..size-1 (size 1..kMaxSymbols).
class FrequencyModel {
 public:
  static constexpr int kMaxSymbols = 4096;      // > 2*1860+1, the widest FAP range
  static constexpr std::uint16_t kMaxTotal = 16383;
  static constexpr int kMaxIncrement = 64;  // counts grow by 1..kMaxIncrement per coded symbol
  // The table is stored in blocks of kLanes entries (one 16-byte vector each), zero-padded to an
  // even number of blocks, so that searching and updating run over whole blocks without a scalar
  // tail.
  static constexpr std::size_t kLanes = 8;
  // kLanes 16-bit counts in one vector register (GCC and Clang vector extension: SSE2 on x86-64,
  // NEON on ARM, scalar code elsewhere).
  typedef std::int16_t Lanes __attribute__((vector_size(2 * kLanes)));

  FrequencyModel() = default;  // no symbols (size 0): a model nothing is coded with
  explicit FrequencyModel(int size, int increment = 1) { reset(size, increment); }
  // Uniform again over `size` symbols (1..kMaxSymbols); each coded symbol will add `increment`
  // (1..kMaxIncrement) to its count.
  void reset(int size, int increment = 1);
  int size() const { return size_; }
  int increment() const { return increment_; }
  // Counts symbol s (0..size-1): + increment, first halving every count (rounding up) when the
  // total would otherwise pass kMaxTotal (with increment 1: when it is kMaxTotal).
  void update(int s) {
    if (cumulative_[0] + increment_ > kMaxTotal) halve();
    add_increment(s);
  }
  // cumulative(i): the total count of symbols i..size-1 (i = 0..size); cumulative(0) is the total.
  std::uint32_t cumulative(int i) const { return cumulative_[static_cast<std::size_t>(i)]; }
  std::uint32_t total() const { return cumulative_[0]; }
  // floor(length * cumulative(i) / total) for length 1..65536: where the coder's interval of
  // `length` values is cut at i. Exact, by the model's reciprocal of its total.
  std::uint32_t scale(std::uint32_t length, int i) const { return total_reciprocal_.divide(length * cumulative(i)); }
  // The decoder's search: the index i (1..size) with cumulative(i) <= target < cumulative(i-1),
  // i.e. symbol i-1. Precondition: target < cumulative(0).
  int find(std::uint32_t target) const {
    return cumulative_.size() <= kCountedEntries ? count_above(target) : search(target);
  }
  bool operator==(const FrequencyModel&) const = default;

 private:
  // Tables up to this many entries (P models sized to the data) are searched by counting.
  static constexpr std::size_t kCountedEntries = 256;
  // The table descends: the answer is the number of entries above target (the total always is;
  // the zero padding never is), counted block by block without branches, one vector compare each.
  int count_above(std::uint32_t target) const {
    // 0 < target + 1 <= kMaxTotal < 2^15: the comparisons are signed 16-bit ones.
    const Lanes t = Lanes{} + static_cast<std::int16_t>(target);
    // Two blocks a step, into two sums (two short dependency chains instead of one long one).
    Lanes above{}, above2{};  // per lane, minus the count (a true comparison is -1), at most 16 each
    for (std::size_t b = 0; b < cumulative_.size(); b += 2 * kLanes) {
      above += load(b) > t;
      above2 += load(b + kLanes) > t;
    }
    above += above2;
    // The lanes summed as 64-bit words of four: each lane sum stays below 2^16, and the
    // multiplication adds the four into the top 16 bits.
    above = -above;
    std::array<std::uint64_t, kLanes / 4> words{};
    std::memcpy(words.data(), &above, sizeof above);
    std::uint64_t sum = 0;
    for (const std::uint64_t w : words) sum += w;
    return static_cast<int>((sum * 0x0001000100010001u) >> 48);
  }
  // The block of entries from `at` (a multiple of kLanes).
  Lanes load(std::size_t at) const {
    Lanes v;
    std::memcpy(&v, cumulative_.data() + at, sizeof v);
    return v;
  }
  void store(std::size_t at, Lanes v) { std::memcpy(cumulative_.data() + at, &v, sizeof v); }
  int search(std::uint32_t target) const;  // binary search, for large tables
  void halve();
  // Entries 0..s grow by the increment: whole blocks, then the block holding s through a mask.
  void add_increment(int s);

  std::vector<std::uint16_t> cumulative_;  // size+1 entries, descending, last 0; zeros to a pair of blocks
  int size_ = 0;
  std::int16_t increment_ = 1;
  ExactReciprocal total_reciprocal_;  // of cumulative_[0]
};

// The coder's interval after the renormalisation shifts, and how many there were (0..16).
struct ArithmeticInterval {
  std::uint32_t low = 0, high = 0;
  int shifts = 0;
  bool operator==(const ArithmeticInterval&) const = default;
};

// Renormalises low <= high (16-bit) as spec/fba.md §7 says, one shift while high < 32768,
// low >= 32768 or 16384 <= low, high < 49152, but without a loop: the top bits low and high share
// leave at once (the first two cases), then the middle case, which repeats while low's next bit
// is 1 and high's is 0 (each step drops that bit and keeps bit 15), at once too. The middle case
// cannot bring back a shared top bit: low's bit 15 stays 0 and high's 1.
// (Each count runs on a 32-bit word with a 1 planted below the bits counted, so it is never 0
// and needs no zero test.)
constexpr ArithmeticInterval arithmetic_renormalise(std::uint32_t low, std::uint32_t high) {
  const int same = std::countl_zero(((low ^ high) << 16) | 0x8000u);  // 0..16
  low = (low << same) & 0xFFFFu;
  high = ((high << same) | ((1u << same) - 1)) & 0xFFFFu;
  // Leading 1s of low and leading 0s of high below bit 15, 0..15 each.
  const int middle = std::min(std::countl_zero((~low << 17) | 0x10000u), std::countl_zero((high << 17) | 0x10000u));
  return {(low << middle) & 0x7FFFu, ((high << middle) & 0x7FFFu) | 0x8000u | ((1u << middle) - 1), same + middle};
}

class ArithmeticEncoder {
 public:
  // Starts a segment (the writer's stuffing scope, fba_bits.hpp).
  explicit ArithmeticEncoder(FbaBitWriter& out) : out_(out) { out_.begin_segment(); }
  // Codes symbol s (0..model.size()-1) and counts it in the model.
  void encode(int s, FrequencyModel& model) {
    encode_only(s, model);
    model.update(s);
  }
  // Codes symbol s without counting it: a caller that may still take the plane back counts it
  // later (each model codes at most one symbol per plane, so the order does not matter).
  void encode_only(int s, const FrequencyModel& model);
  // Ends the segment: one bit plus the pending opposite bits (2 + pending bits in all).
  void flush();

 private:
  void bit_plus_follow(int bit);
  FbaBitWriter& out_;
  std::uint32_t low_ = 0, high_ = 65535, pending_ = 0;
};

class ArithmeticDecoder {
 public:
  // Starts a segment (the reader's stuffing scope) and reads 16 bits of look-ahead.
  explicit ArithmeticDecoder(FbaBitReader& in);
  // Decodes one symbol (0..model.size()-1) and counts it in the model. Inline: it is the
  // decoder's inner loop.
  int decode(FrequencyModel& model) {
    const int s = decode_only(model);
    model.update(s);
    return s;
  }
  // Decodes one symbol without counting it (the standard's intra models, uniform bit models).
  int decode_only(const FrequencyModel& model) {
    const std::uint32_t length = high_ - low_ + 1;
    const std::uint32_t cum = ((offset_ + 1) * model.total() - 1) / length;
    const int i = model.find(cum);
    const std::uint32_t below = model.scale(length, i);
    const ArithmeticInterval next = arithmetic_renormalise(low_ + below, low_ - 1 + model.scale(length, i - 1));
    // The code value moves with low, so only offset = value - low takes the shifted-in bits.
    offset_ = ((offset_ - below) << next.shifts) | in_.lookahead_bits(next.shifts);
    low_ = next.low;
    high_ = next.high;
    return i - 1;
  }
  // Ends the segment at the bits the encoder wrote: gives back the 14 look-ahead payload bits
  // (counted after de-stuffing, so neither a stuffed bit in the look-ahead nor one the reader
  // only thought it saw there shifts the reader).
  void finish();

 private:
  FbaBitReader& in_;
  std::uint32_t low_ = 0, high_ = 65535;
  std::uint32_t offset_ = 0;  // value - low: the code value's place in the interval, < high - low + 1
};

}  // namespace fapcast
