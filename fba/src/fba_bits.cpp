#include "fba_bits.hpp"

#include "fapcast/fba/fba_errc.hpp"

#include <cassert>

namespace fapcast {

void FbaBitWriter::start_code(std::uint32_t code) {
  assert(pos_.raw_bits % 8 == 0);
  for (int shift = 24; shift >= 0; shift -= 8) bytes_.push_back(static_cast<std::uint8_t>(code >> shift));
  pos_.raw_bits += 32;
  pos_.zero_run = 0;
}

void FbaBitWriter::raw_bit(int bit) {
  if (pos_.raw_bits % 8 == 0) bytes_.push_back(0);
  if (bit) bytes_.back() |= static_cast<std::uint8_t>(0x80u >> (pos_.raw_bits % 8));
  ++pos_.raw_bits;
}

void FbaBitWriter::put_bit(int bit) {
  raw_bit(bit);
  if (bit) {
    pos_.zero_run = 0;
  } else if (++pos_.zero_run == kStuffAfterZeros) {
    raw_bit(1);  // emulation prevention
    pos_.zero_run = 0;
  }
}

void FbaBitWriter::put(std::uint32_t value, int count) {
  for (int i = count - 1; i >= 0; --i) put_bit(static_cast<int>((value >> i) & 1u));
}

void FbaBitWriter::align() {
  while (pos_.raw_bits % 8 != 0) raw_bit(1);
  pos_.zero_run = 0;
}

int FbaBitReader::raw_bit(bool allow_past_end) {
  const std::uint64_t at = pos_.raw_bits++;
  if (at >= size_bits_) {
    if (!allow_past_end) fail(fba_errc::truncated);
    return 0;
  }
  return (bytes_[at / 8] >> (7 - at % 8)) & 1;
}

int FbaBitReader::payload_bit(bool allow_past_end) {
  ++payload_bits_;
  const int bit = raw_bit(allow_past_end);
  if (bit) {
    pos_.zero_run = 0;
  } else if (++pos_.zero_run == kStuffAfterZeros) {
    check_stuffed_bit(allow_past_end);
  }
  return bit;
}

void FbaBitReader::check_stuffed_bit(bool allow_past_end) {
  pos_.zero_run = 0;
  last_stuffed_ = payload_bits_;
  const bool inside = pos_.raw_bits < size_bits_;
  if (raw_bit(allow_past_end) != 1 && inside) fail(fba_errc::stuffing_bit_missing);
}

std::uint32_t FbaBitReader::get_slow(int count, bool allow_past_end) {
  std::uint32_t value = 0;
  for (int i = 0; i < count; ++i) value = (value << 1) | static_cast<std::uint32_t>(payload_bit(allow_past_end));
  return error_ ? 0 : value;
}

void FbaBitReader::marker() {
  if (get_bit() != 1) fail(fba_errc::marker_bit_missing);
}

void FbaBitReader::unread(int count) {
  assert(count >= 0 && count <= 16);
  if (count == 0) return;
  // At most one stuffed bit lies among 16 payload bits (22 zeros come between two); it was
  // among the given-back ones if it came after the first of them.
  const std::uint64_t back_to = payload_bits_ - static_cast<std::uint64_t>(count);
  const bool stuffed_inside = last_stuffed_ > back_to;
  payload_bits_ = back_to;
  pos_.raw_bits -= static_cast<std::uint64_t>(count) + (stuffed_inside ? 1 : 0);
  if (stuffed_inside) last_stuffed_ = 0;
  // The zero run is the 0 bits just before the position (stuffed and alignment bits are 1).
  pos_.zero_run = 0;
  for (std::uint64_t at = pos_.raw_bits; at > 0 && pos_.zero_run < kStuffAfterZeros; --at) {
    const std::uint64_t bit = at - 1;
    if (bit < size_bits_ && ((bytes_[bit / 8] >> (7 - bit % 8)) & 1)) break;
    ++pos_.zero_run;
  }
}

void FbaBitReader::expect_end() {
  if (pos_.raw_bits > size_bits_) fail(fba_errc::truncated);
  if (error_) return;
  while (pos_.raw_bits % 8 != 0) {
    if (raw_bit(false) != 1) fail(fba_errc::bad_alignment_bits);
  }
  if (!error_ && pos_.raw_bits != size_bits_) fail(fba_errc::trailing_bytes);
}

}  // namespace fapcast
