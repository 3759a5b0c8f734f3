#pragma once
// CRC-32 (IEEE 802.3 / zlib / PNG: reflected polynomial 0xEDB88320, initial and final XOR
// 0xFFFFFFFF), computed by libdeflate (carry-less multiplication where the CPU has it: a 15 MB
// voice file in about 2 ms of CPU, zlib's crc32_z 4x that; tests/bench/crc32_bench.cpp).
// Check value: crc32("123456789") = 0xCBF43926.
#include <cstddef>
#include <cstdint>
#include <span>

namespace fapcast {

// CRC-32 of `bytes`; pass a previous result as `crc` to continue over a split buffer.
std::uint32_t crc32(std::span<const std::byte> bytes, std::uint32_t crc = 0);

}  // namespace fapcast
