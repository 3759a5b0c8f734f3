#include "fapcast/codec/arithmetic_coder.hpp"

#include "fapcast/codec/fba_errc.hpp"

#include <algorithm>
#include <bit>
#include <cassert>

namespace fapcast::codec {
namespace {
constexpr std::uint32_t kQuarter = 16384, kHalf = 32768, kThreeQuarters = 49152;
constexpr int kLookaheadBits = 16;
constexpr int kGiveBackBits = 14;  // look-ahead 16 minus the 2 bits a flush writes beyond the shifts
}  // namespace

void FrequencyModel::reset(int size) {
  assert(size >= 1 && size <= kMaxSymbols);
  cumulative_.resize(static_cast<std::size_t>(size) + 1);
  for (int i = 0; i <= size; ++i) cumulative_[static_cast<std::size_t>(i)] = static_cast<std::uint16_t>(size - i);
}

int FrequencyModel::find(std::uint32_t target) const {
  // The table descends: the answer is 1 + the number of entries after the total above target.
  // Small tables (every P model the encoder sizes to its data) are counted without branches,
  // which compilers vectorise; large ones (intra models at fap_quant 0) are searched.
  const std::size_t n = cumulative_.size();
  if (n <= 257) {
    const auto t = static_cast<std::uint16_t>(target);  // target < total <= kMaxTotal
    const std::uint16_t* c = cumulative_.data();
    std::uint16_t above = 0;
    for (std::size_t i = 1; i < n; ++i) above = static_cast<std::uint16_t>(above + (c[i] > t ? 1 : 0));
    return 1 + above;
  }
  const auto it = std::partition_point(cumulative_.begin() + 1, cumulative_.end() - 1,
                                       [target](std::uint16_t c) { return c > target; });
  return static_cast<int>(it - cumulative_.begin());
}

void FrequencyModel::update(int s) {
  if (cumulative_[0] + kIncrement > kMaxTotal) {
    // Halve each count (keeping it >= 1) and rebuild the running sums from the top.
    std::uint16_t sum = 0;
    for (std::size_t i = cumulative_.size() - 1; i-- > 0;) {
      const int count = cumulative_[i] - cumulative_[i + 1];
      sum = static_cast<std::uint16_t>(sum + (count + 1) / 2);
      cumulative_[i] = sum;
    }
  }
  for (int i = 0; i <= s; ++i) cumulative_[static_cast<std::size_t>(i)] = static_cast<std::uint16_t>(cumulative_[static_cast<std::size_t>(i)] + kIncrement);
}

void ArithmeticEncoder::bit_plus_follow(int bit) {
  out_.put_bit(bit);
  for (; pending_ > 0; --pending_) out_.put_bit(!bit);
}

void ArithmeticEncoder::encode(int s, FrequencyModel& model) {
  assert(s >= 0 && s < model.size());
  const std::uint32_t length = high_ - low_ + 1;
  const std::uint32_t total = model.cumulative(0);
  high_ = low_ - 1 + length * model.cumulative(s) / total;
  low_ += length * model.cumulative(s + 1) / total;
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
  model.update(s);
}

void ArithmeticEncoder::flush() {
  ++pending_;
  bit_plus_follow(low_ < kQuarter ? 0 : 1);
  low_ = 0;
  high_ = 65535;
}

ArithmeticDecoder::ArithmeticDecoder(FbaBitReader& in) : in_(in), offset_(in_.lookahead_bits(kLookaheadBits)) {}

int ArithmeticDecoder::decode(FrequencyModel& model) {
  const std::uint32_t length = high_ - low_ + 1;
  const std::uint32_t total = model.cumulative(0);
  const std::uint32_t cum = ((offset_ + 1) * total - 1) / length;
  const int i = model.find(cum);
  const std::uint32_t below = length * model.cumulative(i) / total;
  std::uint32_t high = low_ - 1 + length * model.cumulative(i - 1) / total;
  std::uint32_t low = low_ + below;
  std::uint32_t offset = offset_ - below;
  // Renormalise as the encoder does, in bulk: the top bits low and high share leave together
  // (the "emit 0" and "emit 1" cases), then the middle case one shift at a time. The code value
  // moves with low, so only offset = value - low takes the shifted-in bits, all at once (at most
  // 16: the interval is never empty).
  int shifts = 0;
  for (;;) {
    const int same = std::countl_zero(static_cast<std::uint16_t>(low ^ high));
    if (same > 0) {
      low = (low << same) & 0xFFFFu;
      high = ((high << same) | ((1u << same) - 1)) & 0xFFFFu;
      shifts += same;
    }
    if (low < kQuarter || high >= kThreeQuarters) break;
    low = 2 * (low - kQuarter);
    high = 2 * (high - kQuarter) + 1;
    ++shifts;
  }
  if (shifts > 0) offset = (offset << shifts) | in_.lookahead_bits(shifts);
  low_ = low;
  high_ = high;
  offset_ = offset;
  model.update(i - 1);
  return i - 1;
}

void ArithmeticDecoder::finish() {
  in_.unread(kGiveBackBits);
  if (in_.past_end()) in_.fail(fba_errc::truncated);
}

}  // namespace fapcast::codec
