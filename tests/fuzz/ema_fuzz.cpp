// Fuzzes read_ema: any input either reads or throws InputError, never crashes or over-allocates;
// what it reads is a consistent marker set that write_ema_est writes and read_ema reads back to
// the same coils, frames, rate (to a relative 1e-12) and numbering (values to double rounding of x100 / 100).
#include "fapcast/corpus/ema.hpp"
#include "fapcast/core/input_error.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fapcast::MarkerFrames<fapcast::Millimetres> m;
  try {
    m = fapcast::read_ema(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz");
  } catch (const fapcast::InputError&) {
    return 0;
  }
  if (!m.consistent() || m.labels.empty() || !(m.frame_rate_hz > 0)) std::abort();
  const fapcast::MarkerFrames<fapcast::Millimetres> back =
      fapcast::read_ema(fapcast::write_ema_est(m, fapcast::EstEncoding::ascii), "fuzz-back");
  // The rate to a relative 1e-12: the file holds 1 / rate as a shortest decimal, read back as 1 / that.
  if (back.labels != m.labels || std::abs(back.frame_rate_hz - m.frame_rate_hz) > 1e-12 * m.frame_rate_hz ||
      back.first_frame != m.first_frame ||
      back.frame_count() != m.frame_count()) {
    std::abort();
  }
  for (Eigen::Index k = 0; k < m.frame_count(); ++k) {
    for (Eigen::Index r = 0; r < m.positions.rows(); ++r) {
      const double a = m.positions(r, k), b = back.positions(r, k);
      if (std::isnan(a) != std::isnan(b) || (!std::isnan(a) && std::abs(a - b) > 1e-12 * (1 + std::abs(a)))) std::abort();
    }
  }
  return 0;
}
