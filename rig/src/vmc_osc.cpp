#include "fapcast/rig/vmc_osc.hpp"

#include <bit>
#include <cstring>
#include <stdexcept>

namespace fapcast {

namespace {
void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(v >> shift));
}
void put_string(std::vector<std::uint8_t>& out, std::string_view s) {
  out.insert(out.end(), s.begin(), s.end());
  const std::size_t pad = 4 - s.size() % 4;  // at least one NUL
  out.insert(out.end(), pad, 0);
}
void check_name(std::string_view s) {
  if (s.empty() || s.find('\0') != std::string_view::npos)
    throw std::invalid_argument("OSC string must be non-empty and hold no NUL");
}
}  // namespace

std::vector<std::uint8_t> osc_message(std::string_view address, std::span<const OscArgument> arguments) {
  check_name(address);
  std::vector<std::uint8_t> out;
  put_string(out, address);
  std::string tags = ",";
  for (const OscArgument& a : arguments) {
    if (a.type != 'i' && a.type != 'f' && a.type != 's') throw std::invalid_argument("OSC type must be i, f or s");
    tags += a.type;
  }
  put_string(out, tags);
  for (const OscArgument& a : arguments) {
    if (a.type == 'i') put32(out, static_cast<std::uint32_t>(a.i));
    else if (a.type == 'f') put32(out, std::bit_cast<std::uint32_t>(a.f));
    else { check_name(a.s); put_string(out, a.s); }
  }
  return out;
}

std::vector<std::uint8_t> vmc_blend_bundle(std::span<const std::string> names, std::span<const float> values,
                                           float time_s) {
  if (names.size() != values.size()) throw std::invalid_argument("vmc_blend_bundle: names and values differ in length");
  std::vector<std::uint8_t> out;
  put_string(out, "#bundle");
  put32(out, 0);
  put32(out, 1);  // time tag 1: immediately
  auto element = [&](const std::vector<std::uint8_t>& m) {
    put32(out, static_cast<std::uint32_t>(m.size()));
    out.insert(out.end(), m.begin(), m.end());
  };
  OscArgument one{'i', 1, 0, {}};
  element(osc_message("/VMC/Ext/OK", std::span(&one, 1)));
  OscArgument t{'f', 0, time_s, {}};
  element(osc_message("/VMC/Ext/T", std::span(&t, 1)));
  for (std::size_t i = 0; i < names.size(); ++i) {
    const OscArgument args[2] = {{'s', 0, 0, names[i]}, {'f', 0, values[i], {}}};
    element(osc_message("/VMC/Ext/Blend/Val", args));
  }
  element(osc_message("/VMC/Ext/Blend/Apply", {}));
  return out;
}

}  // namespace fapcast
