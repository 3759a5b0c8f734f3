#include "arithmetic_coder.hpp"

#include "fapcast/fba/fba_errc.hpp"

#include <algorithm>
#include <array>
#include <cassert>

namespace fapcast {
namespace {
constexpr std::uint32_t kQuarter = 16384, kHalf = 32768, kThreeQuarters = 49152;
constexpr int kLookaheadBits = 16;
constexpr int kGiveBackBits = 14;  // look-ahead 16 minus the 2 bits a flush writes beyond the shifts

// The reciprocal of every total a model can have (1..kMaxTotal), so that an update looks its
// reciprocal up instead of dividing (128 KiB, computed at compile time).
constexpr auto kTotalReciprocals = [] {
  std::array<ExactReciprocal, FrequencyModel::kMaxTotal + 1> r{};
  for (std::uint32_t total = 1; total <= FrequencyModel::kMaxTotal; ++total) r[total] = ExactReciprocal(total);
  return r;
}();

// kTailMasks[k]: all ones on the first k + 1 lanes of a block, 0 on the rest.
const auto kTailMasks = [] {
  std::array<FrequencyModel::Lanes, FrequencyModel::kLanes> t{};
  for (std::size_t k = 0; k < t.size(); ++k)
    for (std::size_t j = 0; j <= k; ++j) t[k][j] = -1;
  return t;
}();

std::size_t whole_blocks(std::size_t entries) {
  constexpr std::size_t pair = 2 * FrequencyModel::kLanes;
  return (entries + pair - 1) / pair * pair;
}

}  // namespace

void FrequencyModel::reset(int size, int increment) {
  assert(size >= 1 && size <= kMaxSymbols && increment >= 1 && increment <= kMaxIncrement);
  size_ = size;
  increment_ = static_cast<std::int16_t>(increment);
  cumulative_.resize(whole_blocks(static_cast<std::size_t>(size) + 1));
  // Entry i is size - i (every count 1), the padding 0: a block at a time.
  static_assert(kLanes == 8, "the lane offsets below");
  const Lanes first = static_cast<std::int16_t>(size) - Lanes{0, 1, 2, 3, 4, 5, 6, 7};
  for (std::size_t b = 0; b < cumulative_.size(); b += kLanes) {
    const Lanes v = first - static_cast<std::int16_t>(b);
    store(b, v & (v > 0));
  }
  total_reciprocal_ = kTotalReciprocals[cumulative_[0]];
}

int FrequencyModel::search(std::uint32_t target) const {
  const auto it = std::partition_point(cumulative_.begin() + 1, cumulative_.begin() + size_,
                                       [target](std::uint16_t e) { return e > target; });
  return static_cast<int>(it - cumulative_.begin());
}

void FrequencyModel::halve() {
  // Each count halved (keeping it >= 1), the running sums rebuilt from the top.
  std::uint16_t* c = cumulative_.data();
  std::uint16_t sum = 0;
  for (int i = size_; i-- > 0;) {
    const int count = c[i] - c[i + 1];
    sum = static_cast<std::uint16_t>(sum + (count + 1) / 2);
    c[i] = sum;
  }
}

void FrequencyModel::add_increment(int s) {
  const auto last = static_cast<std::size_t>(s);
  const std::size_t whole = last / kLanes * kLanes;
  const Lanes increment = Lanes{} + increment_;
  for (std::size_t b = 0; b < whole; b += kLanes) store(b, load(b) + increment);
  store(whole, load(whole) + (increment & kTailMasks[last - whole]));
  total_reciprocal_ = kTotalReciprocals[cumulative_[0]];
}

void ArithmeticEncoder::bit_plus_follow(int bit) {
  out_.put_bit(bit);
  for (; pending_ > 0; --pending_) out_.put_bit(!bit);
}

void ArithmeticEncoder::encode_only(int s, const FrequencyModel& model) {
  assert(s >= 0 && s < model.size());
  const std::uint32_t length = high_ - low_ + 1;
  high_ = low_ - 1 + model.scale(length, s);
  low_ += model.scale(length, s + 1);
  for (;;) {
    if (high_ < kHalf) {
      bit_plus_follow(0);
    } else if (low_ >= kHalf) {
      bit_plus_follow(1);
      low_ -= kHalf;
      high_ -= kHalf;
    } else if (low_ >= kQuarter && high_ < kThreeQuarters) {
      ++pending_;
      low_ -= kQuarter;
      high_ -= kQuarter;
    } else {
      break;
    }
    low_ = 2 * low_;
    high_ = 2 * high_ + 1;
  }
}

void ArithmeticEncoder::flush() {
  ++pending_;
  bit_plus_follow(low_ < kQuarter ? 0 : 1);
  low_ = 0;
  high_ = 65535;
  out_.end_segment();
}

ArithmeticDecoder::ArithmeticDecoder(FbaBitReader& in)
    : in_((in.begin_segment(), in)), offset_(in_.lookahead_bits(kLookaheadBits)) {}

void ArithmeticDecoder::finish() {
  in_.end_segment(kGiveBackBits);
  if (in_.past_end()) in_.fail(fba_errc::truncated);
}

}  // namespace fapcast
