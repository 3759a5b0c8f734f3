#pragma once
// The adaptive arithmetic coder of the FBA stream, after H.263 Annex E: 16-bit registers
// (top 65535, quarter points 16384, 32768, 49152), cumulative-frequency tables descending with
// the total first, every model starting uniform, all counts halved before the total would pass
// 16383. fapcast: a coded symbol's count grows by kIncrement = 8, not 1 (spec/fba.md §7), so a
// model learns a peaked distribution within the few symbols of one intra period. Encoder and
// decoder mirror each other over one model type.
#include "fapcast/codec/fba_bits.hpp"

#include <cstdint>
#include <vector>

namespace fapcast::codec {

// An adaptive frequency model over the symbols 0..size-1 (size 1..kMaxSymbols).
class FrequencyModel {
 public:
  static constexpr int kMaxSymbols = 4096;      // > 2*1860+1, the widest FAP range
  static constexpr std::uint16_t kMaxTotal = 16383;
  static constexpr int kIncrement = 8;  // fapcast; the notes' codec adds 1

  FrequencyModel() = default;
  explicit FrequencyModel(int size) { reset(size); }
  // Uniform again over `size` symbols (1..kMaxSymbols).
  void reset(int size);
  int size() const { return static_cast<int>(cumulative_.size()) - 1; }
  // Counts symbol s (0..size-1): + kIncrement, first halving every count (rounding up) when the
  // total would otherwise pass kMaxTotal.
  void update(int s);
  // cumulative(i): the total count of symbols i..size-1; cumulative(0) is the total.
  std::uint32_t cumulative(int i) const { return cumulative_[static_cast<std::size_t>(i)]; }
  // The decoder's search: the index i (1..size) with cumulative(i) <= target < cumulative(i-1),
  // i.e. symbol i-1. Precondition: target < cumulative(0).
  int find(std::uint32_t target) const;
  bool operator==(const FrequencyModel&) const = default;

 private:
  std::vector<std::uint16_t> cumulative_;  // size+1 entries, descending, last 0
};

class ArithmeticEncoder {
 public:
  explicit ArithmeticEncoder(FbaBitWriter& out) : out_(out) {}
  // Codes symbol s (0..model.size()-1) and counts it in the model.
  void encode(int s, FrequencyModel& model);
  // Ends the segment: one bit plus the pending opposite bits (2 + pending bits in all).
  void flush();

 private:
  void bit_plus_follow(int bit);
  FbaBitWriter& out_;
  std::uint32_t low_ = 0, high_ = 65535, pending_ = 0;
};

class ArithmeticDecoder {
 public:
  // Starts a segment: reads 16 bits of look-ahead.
  explicit ArithmeticDecoder(FbaBitReader& in);
  // Decodes one symbol (0..model.size()-1) and counts it in the model.
  int decode(FrequencyModel& model);
  // Ends the segment at the bits the encoder wrote: gives back the 14 look-ahead payload bits
  // (counted after de-stuffing, so a stuffed bit in the look-ahead does not shift the reader).
  void finish();

 private:
  FbaBitReader& in_;
  std::uint32_t low_ = 0, high_ = 65535;
  std::uint32_t offset_ = 0;  // value - low: the code value's place in the interval, < high - low + 1
};

}  // namespace fapcast::codec
