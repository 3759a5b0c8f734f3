#pragma once
// The VMC protocol's blend-shape messages as OSC 1.0 packets (spec/rigs.md, "VMC"): one bundle
// per frame, time tag 1 ("immediately"), holding /VMC/Ext/OK (int 1: model loaded), /VMC/Ext/T
// (float seconds since the stream began), one /VMC/Ext/Blend/Val (string name, float value) per
// blend shape, and /VMC/Ext/Blend/Apply (no arguments). OSC strings are NUL-terminated and padded
// with NULs to a multiple of 4 bytes; int32 and float32 big-endian; every element of a bundle is
// preceded by its size (int32).
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fapcast {

// Throws std::invalid_argument when names and values differ in length or a name is empty or holds
// a NUL.
std::vector<std::uint8_t> vmc_blend_bundle(std::span<const std::string> names, std::span<const float> values,
                                           float time_s);

// One OSC message (address, type tags from the arguments): for tests and other VMC messages.
struct OscArgument {
  char type;            // 'i', 'f' or 's'
  std::int32_t i = 0;
  float f = 0;
  std::string s;
};
std::vector<std::uint8_t> osc_message(std::string_view address, std::span<const OscArgument> arguments);

}  // namespace fapcast
