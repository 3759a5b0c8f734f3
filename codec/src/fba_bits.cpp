#include "fapcast/codec/fba_bits.hpp"

#include "fapcast/codec/fba_errc.hpp"

#include <cassert>

namespace fapcast::codec {

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

void FbaBitReader::fail_truncated() { fail(fba_errc::truncated); }

void FbaBitReader::check_stuffed_bit(bool allow_past_end) {
  pos_.zero_run = 0;
  const bool inside = pos_.raw_bits < 8 * bytes_.size();
  if (raw_bit(allow_past_end) != 1 && inside) fail(fba_errc::stuffing_bit_missing);
}

std::uint32_t FbaBitReader::get(int count) {
  std::uint32_t value = 0;
  for (int i = 0; i < count; ++i) value = (value << 1) | static_cast<std::uint32_t>(get_bit());
  return error_ ? 0 : value;
}

void FbaBitReader::marker() {
  if (get_bit() != 1) fail(fba_errc::marker_bit_missing);
}

void FbaBitReader::unread(int count) {
  assert(count >= 0 && count <= static_cast<int>(history_.size()));
  if (count == 0) return;
  payload_bits_ -= static_cast<std::uint32_t>(count);
  pos_ = history_[payload_bits_ % history_.size()];
}

void FbaBitReader::expect_end() {
  if (pos_.raw_bits > 8 * bytes_.size()) fail(fba_errc::truncated);
  if (error_) return;
  while (pos_.raw_bits % 8 != 0) {
    if (raw_bit(false) != 1) fail(fba_errc::bad_alignment_bits);
  }
  if (!error_ && pos_.raw_bits != 8 * bytes_.size()) fail(fba_errc::trailing_bytes);
}

}  // namespace fapcast::codec
