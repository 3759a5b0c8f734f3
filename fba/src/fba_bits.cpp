#include "fba_bits.hpp"

#include "fapcast/fba/fba_errc.hpp"

#include <cassert>

namespace fapcast {

// --- writer -------------------------------------------------------------------------------------

void FbaBitWriter::start_code(std::uint32_t code) {
  assert(pos_.raw_bits % 8 == 0 && !in_segment_);
  for (int shift = 24; shift >= 0; shift -= 8) bytes_.push_back(static_cast<std::uint8_t>(code >> shift));
  pos_.raw_bits += 32;
  pos_.zero_run = 0;
}

void FbaBitWriter::stuff_to_start_code() {
  assert(!in_segment_);
  raw_bit(0);
  while (pos_.raw_bits % 8 != 0) raw_bit(1);
  pos_.zero_run = 0;
}

void FbaBitWriter::raw_bit(int bit) {
  if (pos_.raw_bits % 8 == 0) bytes_.push_back(0);
  if (bit) bytes_.back() |= static_cast<std::uint8_t>(0x80u >> (pos_.raw_bits % 8));
  ++pos_.raw_bits;
}

void FbaBitWriter::put_bit(int bit) {
  if (stuffing_ == FbaStuffing::kContinuous) {
    raw_bit(bit);
    if (bit) {
      pos_.zero_run = 0;
    } else if (++pos_.zero_run == kStuffAfterZeros) {
      stuffed_.push_back(pos_.raw_bits);
      raw_bit(1);  // emulation prevention, right after the 22nd zero
      pos_.zero_run = 0;
    }
    return;
  }
  if (!in_segment_) {  // kReference: header and raw fields are neither counted nor stuffed
    raw_bit(bit);
    return;
  }
  if (pos_.zero_run == kStuffAfterZeros) {  // before the bit that would be the 23rd zero
    stuffed_.push_back(pos_.raw_bits);
    raw_bit(1);
    pos_.zero_run = 0;
  }
  raw_bit(bit);
  pos_.zero_run = bit ? 0 : pos_.zero_run + 1;
}

void FbaBitWriter::put(std::uint32_t value, int count) {
  for (int i = count - 1; i >= 0; --i) put_bit(static_cast<int>((value >> i) & 1u));
}

void FbaBitWriter::begin_segment() {
  in_segment_ = true;
  if (stuffing_ == FbaStuffing::kReference) pos_.zero_run = 0;
  segments_.push_back({pos_.raw_bits, pos_.raw_bits});
}

void FbaBitWriter::end_segment() {
  in_segment_ = false;
  if (stuffing_ == FbaStuffing::kReference) pos_.zero_run = 0;
  if (!segments_.empty()) segments_.back().end = pos_.raw_bits;
}

FbaBitWriter::Mark FbaBitWriter::mark() {
  segments_.clear();
  stuffed_.clear();
  return {bytes_.size(), bytes_.empty() ? std::uint8_t{0} : bytes_.back(), pos_, in_segment_};
}

void FbaBitWriter::rollback(const Mark& m) {
  bytes_.resize(m.bytes);
  if (!bytes_.empty()) bytes_.back() = m.last_byte;  // the bits after the mark in a shared byte
  pos_ = m.pos;
  in_segment_ = m.in_segment;
  segments_.clear();
  stuffed_.clear();
}

// --- reader -------------------------------------------------------------------------------------

int FbaBitReader::raw_bit(bool allow_past_end) {
  const std::uint64_t at = pos_.raw_bits++;
  if (at >= size_bits_) {
    if (!allow_past_end) fail(fba_errc::truncated);
    return 0;
  }
  return (bytes_[at / 8] >> (7 - at % 8)) & 1;
}

int FbaBitReader::payload_bit(bool allow_past_end) {
  if (!counting_) return raw_bit(allow_past_end);
  if (stuffing_ == FbaStuffing::kReference && pos_.zero_run == kStuffAfterZeros) {
    // The encoder stuffed a 1 before the bit it wrote next, if it wrote one (end_segment decides).
    const std::uint64_t at = pos_.raw_bits;
    pos_.zero_run = 0;
    if (raw_bit(allow_past_end) == 1 || at >= size_bits_) {
      last_stuffed_ = payload_bits_ + 1;  // it belongs to the bit after it
    } else {
      pos_.raw_bits = at;  // not a stuffed bit: the payload bit itself
      stuffing_missing_ = payload_bits_ + 1;
      stuffing_missing_raw_ = at;
    }
  }
  ++payload_bits_;
  const int bit = raw_bit(allow_past_end);
  if (bit) {
    pos_.zero_run = 0;
  } else if (++pos_.zero_run == kStuffAfterZeros && stuffing_ == FbaStuffing::kContinuous) {
    pos_.zero_run = 0;
    last_stuffed_ = payload_bits_;  // it belongs to the zero before it
    const bool inside = pos_.raw_bits < size_bits_;
    if (raw_bit(allow_past_end) != 1 && inside) fail(fba_errc::stuffing_bit_missing);
  }
  return bit;
}

std::uint32_t FbaBitReader::get_slow(int count, bool allow_past_end) {
  std::uint32_t value = 0;
  for (int i = 0; i < count; ++i) value = (value << 1) | static_cast<std::uint32_t>(payload_bit(allow_past_end));
  return error_ ? 0 : value;
}

void FbaBitReader::marker() {
  if (get_bit() != 1) fail(fba_errc::marker_bit_missing);
}

void FbaBitReader::begin_segment() {
  if (stuffing_ == FbaStuffing::kReference) {
    counting_ = true;
    pos_.zero_run = 0;
    last_stuffed_ = 0;
    stuffing_missing_ = 0;
  }
}

void FbaBitReader::end_segment(int give_back) {
  assert(give_back >= 0 && give_back <= 16);
  // At most one stuffed bit lies among 16 payload bits (22 zeros come between two); it was
  // among the given-back ones if the payload bit it belongs to was.
  const std::uint64_t back_to = payload_bits_ - static_cast<std::uint64_t>(give_back);
  const bool stuffed_inside = last_stuffed_ > back_to && !fixed_give_back_;
  payload_bits_ = back_to;
  pos_.raw_bits -= static_cast<std::uint64_t>(give_back) + (stuffed_inside ? 1 : 0);
  if (stuffed_inside) last_stuffed_ = 0;
  if (stuffing_ == FbaStuffing::kReference) {
    if (stuffing_missing_ != 0 && (stuffing_missing_ <= back_to || fixed_give_back_) && !error_) {
      error_ = fba_errc::stuffing_bit_missing;  // a bit the encoder wrote: a real error
      error_bits_ = std::min<std::uint64_t>(stuffing_missing_raw_, size_bits_);
    }
    stuffing_missing_ = 0;
    counting_ = false;
    pos_.zero_run = 0;
    return;
  }
  // The zero run is the 0 bits just before the position (stuffed and alignment bits are 1).
  pos_.zero_run = 0;
  for (std::uint64_t at = pos_.raw_bits; at > 0 && pos_.zero_run < kStuffAfterZeros; --at) {
    const std::uint64_t bit = at - 1;
    if (bit < size_bits_ && ((bytes_[bit / 8] >> (7 - bit % 8)) & 1)) break;
    ++pos_.zero_run;
  }
}

void FbaBitReader::seek(std::uint64_t at) {
  pos_.raw_bits = at;
  pos_.zero_run = 0;
  counting_ = stuffing_ == FbaStuffing::kContinuous;
}

}  // namespace fapcast
