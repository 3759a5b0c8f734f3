#include "fapcast/codec/arithmetic_coder.hpp"

#include "fapcast/codec/fba_errc.hpp"

#include <algorithm>
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
  // The table descends: the first entry after the total that is <= target ends the symbol.
  const auto it = std::partition_point(cumulative_.begin() + 1, cumulative_.end() - 1,
                                       [target](std::uint16_t c) { return c > target; });
  return static_cast<int>(it - cumulative_.begin());
}

void FrequencyModel::update(int s) {
  if (cumulative_[0] >= kMaxTotal) {
    // Halve each count (keeping it >= 1) and rebuild the running sums from the top.
    std::uint16_t sum = 0;
    for (std::size_t i = cumulative_.size() - 1; i-- > 0;) {
      const int count = cumulative_[i] - cumulative_[i + 1];
      sum = static_cast<std::uint16_t>(sum + (count + 1) / 2);
      cumulative_[i] = sum;
    }
  }
  for (int i = 0; i <= s; ++i) ++cumulative_[static_cast<std::size_t>(i)];
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

ArithmeticDecoder::ArithmeticDecoder(FbaBitReader& in) : in_(in) {
  for (int i = 0; i < kLookaheadBits; ++i) value_ = (value_ << 1) | static_cast<std::uint32_t>(in_.lookahead_bit());
}

int ArithmeticDecoder::decode(FrequencyModel& model) {
  const std::uint32_t length = high_ - low_ + 1;
  const std::uint32_t total = model.cumulative(0);
  const std::uint32_t cum = ((value_ - low_ + 1) * total - 1) / length;
  const int i = model.find(cum);
  high_ = low_ - 1 + length * model.cumulative(i - 1) / total;
  low_ += length * model.cumulative(i) / total;
  for (;;) {
    if (high_ < kHalf) {
      // nothing to subtract
    } else if (low_ >= kHalf) {
      value_ -= kHalf;
      low_ -= kHalf;
      high_ -= kHalf;
    } else if (low_ >= kQuarter && high_ < kThreeQuarters) {
      value_ -= kQuarter;
      low_ -= kQuarter;
      high_ -= kQuarter;
    } else {
      break;
    }
    low_ = 2 * low_;
    high_ = 2 * high_ + 1;
    value_ = 2 * value_ + static_cast<std::uint32_t>(in_.lookahead_bit());
  }
  model.update(i - 1);
  return i - 1;
}

void ArithmeticDecoder::finish() {
  in_.unread(kGiveBackBits);
  if (in_.past_end()) in_.fail(fba_errc::truncated);
}

}  // namespace fapcast::codec
