#include "fapcast/rig/live_link_csv.hpp"

#include <array>
#include <charconv>
#include <cstdio>
#include <stdexcept>

#include "fapcast/rig/arkit_shapes.hpp"

namespace fapcast {

namespace {
constexpr std::array<const char*, 9> kRotations{"HeadYaw",   "HeadPitch",    "HeadRoll",   "LeftEyeYaw",   "LeftEyePitch",
                                               "LeftEyeRoll", "RightEyeYaw", "RightEyePitch", "RightEyeRoll"};
void append_value(std::string& out, float v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, static_cast<double>(v), std::chars_format::fixed, 10);
  out.append(buf, r.ptr);
}
}  // namespace

std::string live_link_timecode(std::int64_t frame, FrameRate rate) {
  if (!rate.valid() || frame < 0) throw std::invalid_argument("live_link_timecode: invalid rate or frame");
  const std::int64_t milli = frame_to_sample(frame, rate, SampleRate{60'000});  // thousandths of a 60 fps frame
  const std::int64_t tc_frames = milli / 1000;
  const std::int64_t sub = milli % 1000;
  const std::int64_t ff = tc_frames % 60;
  const std::int64_t total_s = tc_frames / 60;
  char buf[40];
  std::snprintf(buf, sizeof buf, "%02lld:%02lld:%02lld:%02lld.%03lld", static_cast<long long>((total_s / 3600) % 24),
                static_cast<long long>((total_s / 60) % 60), static_cast<long long>(total_s % 60),
                static_cast<long long>(ff), static_cast<long long>(sub));
  return buf;
}

std::string live_link_csv(const Eigen::MatrixXf& arkit, FrameRate rate) {
  if (!rate.valid()) throw std::invalid_argument("live_link_csv: invalid rate");
  if (arkit.cols() != static_cast<Eigen::Index>(kArkitShapeCount))
    throw std::invalid_argument("live_link_csv: " + std::to_string(arkit.cols()) + " columns, want 52");
  std::string out = "Timecode,BlendShapeCount";
  for (const ArkitShape& s : kArkitShapes) {
    out += ',';
    out += live_link_name(s.name);
  }
  for (const char* r : kRotations) (out += ",") += r;
  out += '\n';
  out.reserve(out.size() + static_cast<std::size_t>(arkit.rows()) * (20 + 61 * 13));
  for (Eigen::Index f = 0; f < arkit.rows(); ++f) {
    out += live_link_timecode(f, rate);
    out += ",61";
    for (Eigen::Index c = 0; c < arkit.cols(); ++c) {
      out += ',';
      append_value(out, arkit(f, c));
    }
    for (std::size_t r = 0; r < kRotations.size(); ++r) out += ",0.0000000000";
    out += '\n';
  }
  return out;
}

}  // namespace fapcast
