#include "fapcast/corpus/ema.hpp"

#include "fapcast/core/input_error.hpp"
#include "fapcast/core/text_input.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <vector>

namespace fapcast {
namespace {

constexpr double kHundredthsPerMm = 100;    // MOCHA stores 1/100 mm
constexpr std::int64_t kMaxChannels = 1000;  // MOCHA has 20; bounds the names and the row width
constexpr double kStepTolerance = 0.1;       // a time may miss its grid point by 10 % of a step
constexpr double kWholeRateTolerance = 1e-4; // a rate within 0.01 % of a whole number of Hz is it
constexpr double kMinRateHz = 1;            // EMA runs at 100-1250 Hz; the bounds keep a
constexpr double kMaxRateHz = 100000;       // resampled duration and frame numbers sane
constexpr double kMaxStartS = 1e6;          // a first time up to 11.5 days (double times resolve any step)
constexpr double kMaxValue = 1e8;           // 1 km in 1/100 mm: a coil value beyond is not a position
constexpr std::string_view kMagic = "EST_File";

// MOCHA's channel layout (the EST header of every MOCHA-TIMIT .ema file): the headerless MOCHAtools
// rows carry the same 20 channels in the same order after time and flag. "****" is an
// undocumented coil pair, not read.
constexpr std::array<std::string_view, 20> kMochaChannels = {
    "ui_x", "li_x", "ul_x", "ll_x", "tt_x", "ui_y", "li_y", "ul_y", "ll_y", "tt_y",
    "tb_x", "td_x", "v_x",  "****", "bn_x", "tb_y", "td_y", "v_y",  "****", "bn_y"};

// A time or rate for a message: 6 significant digits, as EST's %f times carry them.
std::string figure(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// What the header (or, headerless, MOCHA's layout) says about the data.
struct Layout {
  std::vector<std::string> channels;           // C names
  bool breaks = true;                          // a break-flag column after the time
  std::optional<double> frame_shift_s;         // EST FrameShift
  std::uint64_t frame_shift_line = 0;          // its line
  std::optional<std::int64_t> frames;          // NumFrames (EST only)
  std::uint64_t frames_line = 0;               // its line
  std::uint64_t channels_line = 0;             // the NumChannels line (0: headerless)
};

struct CoilChannels {
  std::string_view coil;
  std::size_t x, y;
};

// The coils whose x and y channels the layout names, in kMochaCoils order.
std::vector<CoilChannels> find_coils(const Layout& layout, const std::string& source) {
  auto index_of = [&](const std::string& name) -> std::optional<std::size_t> {
    std::optional<std::size_t> found;
    for (std::size_t c = 0; c < layout.channels.size(); ++c) {
      if (layout.channels[c] != name) continue;
      if (found) fail_at_line(source, layout.channels_line, "ema-channel-names", "two channels are named " + name);
      found = c;
    }
    return found;
  };
  std::vector<CoilChannels> coils;
  for (const std::string_view coil : kMochaCoils) {
    const std::optional<std::size_t> x = index_of(std::string(coil) + "_x");
    const std::optional<std::size_t> y = index_of(std::string(coil) + "_y");
    if (x.has_value() != y.has_value()) {
      fail_at_line(source, layout.channels_line, "ema-channel-names",
                   "coil " + std::string(coil) + " has an " + (x ? "x" : "y") + " channel but no " + (x ? "y" : "x"));
    }
    if (x) coils.push_back({coil, *x, *y});
  }
  if (coils.empty()) {
    fail_at_line(source, layout.channels_line, "ema-no-coils",
                 "no channel pair <coil>_x, <coil>_y for a MOCHA coil (li ul ll tt tb td v ui bn)");
  }
  return coils;
}

// Frames as they are read: times, break flags and the coils' values (mm), one frame at a time
// (never sized from a header count).
class FrameSink {
 public:
  explicit FrameSink(std::size_t coils) : coils_(coils) {}
  // Adds a frame; `valid` false (a break) leaves its coils missing, `xy` is ignored then.
  template <class XY>
  void add(double time_s, bool valid, XY&& xy) {
    times_.push_back(time_s);
    for (std::size_t m = 0; m < coils_; ++m) {
      if (!valid) {
        values_.insert(values_.end(), 3, std::nan(""));
        continue;
      }
      const auto [x, y] = xy(m);
      values_.push_back(x / kHundredthsPerMm);
      values_.push_back(y / kHundredthsPerMm);
      values_.push_back(0);
    }
  }
  std::size_t frames() const { return times_.size(); }

  // The frames on their time grid. `at_frame(k, rule, detail)` throws at frame k's location.
  MarkerFrames<Millimetres> finish(const std::vector<CoilChannels>& coils, const Layout& layout, const std::string& source,
                                   const std::function<void(std::size_t, const char*, const std::string&)>& at_frame,
                                   const std::function<void(const char*, const std::string&)>& at_file) const {
    const std::size_t n = times_.size();
    double step = 0;
    if (n >= 2) {
      step = (times_.back() - times_.front()) / static_cast<double>(n - 1);
      if (!(step > 0) || !std::isfinite(step)) {
        at_frame(n - 1, "ema-time-step", "times do not increase (first " + figure(times_.front()) + " s, last " +
                                             figure(times_.back()) + " s)");
      }
      // Each step near the mean one (a dropped frame, a repeated time), then each time near its
      // grid point (a slow drift).
      for (std::size_t k = 1; k < n; ++k) {
        const double d = times_[k] - times_[k - 1];
        if (std::abs(d - step) > kStepTolerance * step) {
          at_frame(k, "ema-time-step", "time " + figure(times_[k]) + " s follows " + figure(times_[k - 1]) +
                                           " s: a step of " + figure(d) + " s where the mean step is " +
                                           figure(step) + " s (a frame dropped, or the rate not constant)");
        }
      }
      for (std::size_t k = 0; k < n; ++k) {
        const double expected = times_.front() + static_cast<double>(k) * step;
        if (std::abs(times_[k] - expected) > kStepTolerance * step) {
          at_frame(k, "ema-time-step", "time " + figure(times_[k]) + " s drifts off the grid of " + figure(step) +
                                           " s steps from " + figure(times_.front()) + " s (expected " +
                                           figure(expected) + " s)");
        }
      }
      // FrameShift's grid must reach the last time within the same tolerance.
      if (layout.frame_shift_s &&
          std::abs(static_cast<double>(n - 1) * (step - *layout.frame_shift_s)) > kStepTolerance * step) {
        fail_at_line(source, layout.frame_shift_line, "ema-frame-shift",
                     "FrameShift " + figure(*layout.frame_shift_s) + " s disagrees with the time column's step " +
                         figure(step) + " s");
      }
    } else if (layout.frame_shift_s) {
      step = *layout.frame_shift_s;
    } else {
      at_file("ema-no-rate", std::to_string(n) + " frame" + (n == 1 ? "" : "s") +
                                 ": the frame rate needs two times (or an EST FrameShift)");
    }
    double rate = layout.frame_shift_s ? 1 / *layout.frame_shift_s : 1 / step;
    if (const double whole = std::round(rate); whole >= 1 && std::abs(rate - whole) <= kWholeRateTolerance * rate) {
      rate = whole;
    }
    if (!(rate >= kMinRateHz && rate <= kMaxRateHz)) {
      at_file("ema-rate", "the frame rate " + figure(rate) + " Hz is outside " + figure(kMinRateHz) + "-" +
                              figure(kMaxRateHz) + " Hz");
    }
    std::int64_t first_frame = 0;
    if (n > 0) {
      const double start = times_.front() * rate;
      if (!(times_.front() >= 0 && times_.front() <= kMaxStartS)) {
        at_frame(0, "ema-start-time", "the first time " + figure(times_.front()) + " s is outside 0-" +
                                          figure(kMaxStartS) + " s");
      }
      if (std::abs(start - std::round(start)) > kStepTolerance) {
        at_frame(0, "ema-start-time", "the first time " + figure(times_.front()) +
                                          " s is not a whole number of frames at " + figure(rate) + " Hz");
      }
      first_frame = static_cast<std::int64_t>(std::round(start));
    }
    MarkerFrames<Millimetres> out;
    for (const CoilChannels& c : coils) out.labels.emplace_back(c.coil);
    out.frame_rate_hz = rate;
    out.first_frame = first_frame;
    // values_ holds frame after frame of x y z per coil: the 3M x F layout, column by column.
    out.positions = Eigen::Map<const Eigen::MatrixXd>(values_.data(), static_cast<Eigen::Index>(3 * coils_),
                                                      static_cast<Eigen::Index>(n));
    return out;
  }

 private:
  std::size_t coils_;
  std::vector<double> times_;
  std::vector<double> values_;
};

// The break flag: 1 a valid frame, 0 a break; anything else is refused (EST writes only these).
std::optional<bool> flag_value(double v) {
  if (v == 1) return true;
  if (v == 0) return false;
  return std::nullopt;
}

// Text data rows (EST ascii after the header, or the whole headerless file), lines numbered
// from `first_line`.
MarkerFrames<Millimetres> read_text_rows(std::string_view bytes, std::uint64_t first_line, const Layout& layout,
                                         const std::string& source) {
  const std::vector<CoilChannels> coils = find_coils(layout, source);
  const std::string text = decode_text(bytes, source, "ema");
  const std::vector<TextLine> lines = split_lines(text);
  const std::size_t fields = 1 + (layout.breaks ? 1 : 0) + layout.channels.size();
  FrameSink sink(coils.size());
  std::vector<std::uint64_t> frame_lines;
  for (const TextLine& line : lines) {
    const std::uint64_t number = line.number + first_line - 1;
    const auto cells = split_whitespace(line.text);
    if (cells.empty()) continue;
    if (layout.frames && static_cast<std::int64_t>(sink.frames()) == *layout.frames) {
      fail_at_line(source, number, "ema-frame-count", "more frames than NumFrames " + std::to_string(*layout.frames));
    }
    if (cells.size() != fields) {
      fail_at_line(source, number, "ema-fields",
                   "a frame has " + std::to_string(fields) + " fields (time" + (layout.breaks ? ", break flag" : "") +
                       ", " + std::to_string(layout.channels.size()) + " channels); this row has " +
                       std::to_string(cells.size()));
    }
    auto number_at = [&](std::size_t i) {
      double v = 0;
      if (!parse_finite(cells[i], v)) {
        fail_at_line(source, number, "ema-bad-number", "\"" + excerpt(cells[i]) + "\" is not a finite number");
      }
      return v;
    };
    const double time_s = number_at(0);
    bool valid = true;
    if (layout.breaks) {
      const std::optional<bool> flag = flag_value(number_at(1));
      if (!flag) fail_at_line(source, number, "ema-bad-flag", "the break flag \"" + excerpt(cells[1]) + "\" is not 0 or 1");
      valid = *flag;
    }
    const std::size_t base = layout.breaks ? 2 : 1;
    auto value_at = [&](std::size_t i) {
      const double v = number_at(i);
      if (std::abs(v) > kMaxValue) {
        fail_at_line(source, number, "ema-bad-number", "\"" + excerpt(cells[i]) + "\" is beyond +-1e8 (1 km)");
      }
      return v;
    };
    sink.add(time_s, valid, [&](std::size_t m) {
      return std::pair{value_at(base + coils[m].x), value_at(base + coils[m].y)};
    });
    frame_lines.push_back(number);
  }
  if (layout.frames && static_cast<std::int64_t>(sink.frames()) != *layout.frames) {
    fail_at_line(source, layout.frames_line, "ema-frame-count",
                 "NumFrames is " + std::to_string(*layout.frames) + " but " + std::to_string(sink.frames()) +
                     " frames follow");
  }
  const std::uint64_t end_line = first_line + lines.size();
  return sink.finish(
      coils, layout, source,
      [&](std::size_t k, const char* rule, const std::string& detail) {
        fail_at_line(source, frame_lines[k], rule, detail);
      },
      [&](const char* rule, const std::string& detail) {
        fail_at_line(source, frame_lines.empty() ? end_line : frame_lines.front(), rule, detail);
      });
}

// Binary data: NumFrames frames of float32 time, [float32 break flag], C float32 channels.
MarkerFrames<Millimetres> read_binary_rows(std::string_view bytes, std::uint64_t data_start, bool big_endian,
                                           const Layout& layout, const std::string& source) {
  const std::vector<CoilChannels> coils = find_coils(layout, source);
  auto fail = [&](std::uint64_t at, const char* rule, const std::string& detail) -> void {
    throw InputError({source, std::nullopt, at}, rule, detail);
  };
  auto f32 = [&](std::uint64_t at) {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) {
      const auto b = static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + static_cast<std::uint64_t>(i)]));
      v |= big_endian ? b << (24 - 8 * i) : b << (8 * i);
    }
    return static_cast<double>(std::bit_cast<float>(v));
  };
  const std::uint64_t row_bytes = 4 * (1 + (layout.breaks ? 1 : 0) + layout.channels.size());
  const std::uint64_t available = bytes.size() - data_start;
  const auto frames = static_cast<std::uint64_t>(*layout.frames);
  if (frames > available / row_bytes) {
    const std::uint64_t cut = available / row_bytes;
    fail(data_start + cut * row_bytes, "ema-truncated",
         "NumFrames " + std::to_string(frames) + " frames of " + std::to_string(row_bytes) + " bytes from byte " +
             std::to_string(data_start) + " run past the end of the " + std::to_string(bytes.size()) +
             "-byte file: frame " + std::to_string(cut) + (available % row_bytes != 0 ? " is cut" : " is missing"));
  }
  if (available > frames * row_bytes) {
    fail(data_start + frames * row_bytes, "ema-trailing-data",
         std::to_string(available - frames * row_bytes) + " bytes follow the " + std::to_string(frames) +
             " frames NumFrames announces");
  }
  FrameSink sink(coils.size());
  const std::uint64_t channels_at = layout.breaks ? 8 : 4;
  for (std::uint64_t k = 0; k < frames; ++k) {
    const std::uint64_t row = data_start + k * row_bytes;
    auto finite_at = [&](std::uint64_t at, const char* what) {
      const double v = f32(at);
      if (!std::isfinite(v)) fail(at, "ema-bad-number", std::string(what) + " of frame " + std::to_string(k) + " is not finite");
      return v;
    };
    const double time_s = finite_at(row, "the time");
    bool valid = true;
    if (layout.breaks) {
      const std::optional<bool> flag = flag_value(f32(row + 4));
      if (!flag) fail(row + 4, "ema-bad-flag", "the break flag of frame " + std::to_string(k) + " is not 0 or 1");
      valid = *flag;
    }
    auto value_at = [&](std::uint64_t at) {
      const double v = finite_at(at, "a coil value");
      if (std::abs(v) > kMaxValue) fail(at, "ema-bad-number", "a coil value of frame " + std::to_string(k) + " is beyond +-1e8 (1 km)");
      return v;
    };
    sink.add(time_s, valid, [&](std::size_t m) {
      return std::pair{value_at(row + channels_at + 4 * coils[m].x), value_at(row + channels_at + 4 * coils[m].y)};
    });
  }
  return sink.finish(
      coils, layout, source,
      [&](std::size_t k, const char* rule, const std::string& detail) { fail(data_start + k * row_bytes, rule, detail); },
      [&](const char* rule, const std::string& detail) { fail(data_start, rule, detail); });
}

struct HeaderField {
  std::string_view value;
  std::uint64_t line;
};

// The EST header (lines up to EST_Header_End) and what follows it.
MarkerFrames<Millimetres> read_est(std::string_view bytes, const std::string& source) {
  std::map<std::string, HeaderField, std::less<>> fields;
  std::vector<std::pair<HeaderField, std::string_view>> channel_lines;  // (index text + line, name)
  std::uint64_t line = 0;
  std::size_t pos = 0;
  std::optional<std::size_t> data_start;
  while (pos < bytes.size()) {
    ++line;
    const std::size_t eol = bytes.find('\n', pos);
    const std::size_t end = eol == std::string_view::npos ? bytes.size() : eol;
    std::string_view text = bytes.substr(pos, end - pos);
    pos = eol == std::string_view::npos ? bytes.size() : eol + 1;
    if (text.ends_with('\r')) text.remove_suffix(1);
    for (const char c : text) {
      if ((c < 0x20 || c > 0x7e) && c != '\t') {
        fail_at_line(source, line, "ema-encoding", "the header holds a byte that is not printable ASCII");
      }
    }
    const std::string_view trimmed = trim(text);
    if (line == 1) {
      if (trimmed != "EST_File Track") {
        fail_at_line(source, 1, "ema-header", "the first line is \"" + excerpt(trimmed) + "\", not \"EST_File Track\"");
      }
      continue;
    }
    if (trimmed == "EST_Header_End") {
      data_start = pos;
      break;
    }
    const auto words = split_whitespace(trimmed);
    if (words.empty()) continue;
    const std::string_view key = words[0];
    const std::string_view value = trim(trimmed.substr(key.size()));
    if (key.starts_with("Channel_")) {
      channel_lines.push_back({{key.substr(8), line}, value});
      continue;
    }
    if (!fields.emplace(std::string(key), HeaderField{value, line}).second) {
      fail_at_line(source, line, "ema-header", std::string(key) + " is given twice");
    }
  }
  if (!data_start) fail_at_line(source, line + 1, "ema-no-header-end", "the header has no EST_Header_End line");
  const std::uint64_t header_lines = line;

  auto field = [&](std::string_view key) -> const HeaderField* {
    const auto it = fields.find(key);
    return it == fields.end() ? nullptr : &it->second;
  };
  auto count = [&](std::string_view key) {
    const HeaderField* f = field(key);
    std::int64_t v = 0;
    if (f == nullptr) fail_at_line(source, header_lines, "ema-header", "the header has no " + std::string(key));
    if (!parse_count(f->value, v)) {
      fail_at_line(source, f->line, "ema-header", std::string(key) + " \"" + excerpt(f->value) + "\" is not a count");
    }
    return v;
  };
  Layout layout;
  layout.frames = count("NumFrames");
  layout.frames_line = field("NumFrames")->line;
  const std::int64_t channels = count("NumChannels");
  layout.channels_line = field("NumChannels")->line;
  if (channels > kMaxChannels) {
    fail_at_line(source, layout.channels_line, "ema-limit",
                 "NumChannels " + std::to_string(channels) + " is over the limit of " + std::to_string(kMaxChannels));
  }
  if (const HeaderField* aux = field("NumAuxChannels"); aux != nullptr && aux->value != "0") {
    fail_at_line(source, aux->line, "ema-header", "auxiliary channels (NumAuxChannels " + excerpt(aux->value) +
                                                      ") are not supported");
  }
  if (const HeaderField* b = field("BreaksPresent")) {
    if (b->value != "true") {
      fail_at_line(source, b->line, "ema-header", "BreaksPresent \"" + excerpt(b->value) +
                                                      "\" is not \"true\" (EST reads a break column whenever it is given)");
    }
  } else {
    layout.breaks = false;
  }
  if (const HeaderField* s = field("FrameShift")) {
    double shift = 0;
    if (!parse_finite(s->value, shift) || !(shift > 0)) {
      fail_at_line(source, s->line, "ema-frame-shift", "FrameShift \"" + excerpt(s->value) + "\" is not a positive number");
    }
    layout.frame_shift_s = shift;
    layout.frame_shift_line = s->line;
  }
  layout.channels.assign(static_cast<std::size_t>(channels), "");
  std::vector<bool> named(static_cast<std::size_t>(channels), false);
  for (const auto& [index, name] : channel_lines) {
    std::int64_t c = 0;
    if (!parse_count(index.value, c) || c >= channels) {
      fail_at_line(source, index.line, "ema-channel-names",
                   "Channel_" + excerpt(index.value) + " is not a channel number below NumChannels " +
                       std::to_string(channels));
    }
    if (named[static_cast<std::size_t>(c)]) {
      fail_at_line(source, index.line, "ema-channel-names", "channel " + std::to_string(c) + " is named twice");
    }
    named[static_cast<std::size_t>(c)] = true;
    layout.channels[static_cast<std::size_t>(c)] = std::string(name);
  }

  const HeaderField* type = field("DataType");
  if (type == nullptr || type->value == "ascii") {
    return read_text_rows(bytes.substr(*data_start), header_lines + 1, layout, source);
  }
  if (type->value != "binary") {
    fail_at_line(source, type->line, "ema-data-type", "DataType \"" + excerpt(type->value) + "\" is not ascii or binary");
  }
  const HeaderField* order = field("ByteOrder");
  if (order == nullptr) fail_at_line(source, header_lines, "ema-byte-order", "a binary track needs a ByteOrder");
  if (order->value != "01" && order->value != "10") {
    fail_at_line(source, order->line, "ema-byte-order",
                 "ByteOrder \"" + excerpt(order->value) + "\" is not 01 (little-endian) or 10 (big-endian)");
  }
  return read_binary_rows(bytes, *data_start, order->value == "10", layout, source);
}

void put_f32(std::string& out, float value, bool big_endian) {
  const auto bits = std::bit_cast<std::uint32_t>(value);
  for (int i = 0; i < 4; ++i) out += static_cast<char>((bits >> (big_endian ? 24 - 8 * i : 8 * i)) & 0xff);
}

}  // namespace

MarkerFrames<Millimetres> read_ema(std::string_view bytes, const std::string& source) {
  if (bytes.starts_with(kMagic)) return read_est(bytes, source);
  Layout mocha;
  mocha.channels.assign(kMochaChannels.begin(), kMochaChannels.end());
  return read_text_rows(bytes, 1, mocha, source);
}

std::string write_ema_est(const MarkerFrames<Millimetres>& markers, EstEncoding encoding) {
  auto refuse = [](const std::string& why) { throw std::invalid_argument("write_ema_est: " + why); };
  if (!markers.consistent()) refuse("inconsistent marker set");
  if (!(markers.frame_rate_hz > 0) || !std::isfinite(markers.frame_rate_hz)) refuse("the frame rate must be positive");
  for (std::size_t m = 0; m < markers.labels.size(); ++m) {
    const std::string& label = markers.labels[m];
    if (std::find(kMochaCoils.begin(), kMochaCoils.end(), label) == kMochaCoils.end()) {
      refuse("label \"" + label + "\" is not a MOCHA coil name");
    }
    if (std::find(markers.labels.begin(), markers.labels.begin() + static_cast<std::ptrdiff_t>(m), label) !=
        markers.labels.begin() + static_cast<std::ptrdiff_t>(m)) {
      refuse("coil " + label + " appears twice");
    }
  }
  const bool binary = encoding != EstEncoding::ascii;
  const bool big_endian = encoding == EstEncoding::binary_big_endian;
  const Eigen::Index coils = markers.marker_count();
  std::vector<bool> valid(static_cast<std::size_t>(markers.frame_count()));
  for (Eigen::Index k = 0; k < markers.frame_count(); ++k) {
    Eigen::Index present = 0;
    for (Eigen::Index m = 0; m < coils; ++m) {
      if (!markers.present(m, k)) continue;
      ++present;
      const Eigen::Vector3d p = markers.at(m, k);
      if (p.z() != 0) refuse("frame " + std::to_string(k) + ": coil " + markers.labels[static_cast<std::size_t>(m)] + " has z != 0");
      for (int i = 0; i < 2; ++i) {
        const double v = p[i] * kHundredthsPerMm;
        if (!std::isfinite(binary ? static_cast<double>(static_cast<float>(v)) : v)) {
          refuse("frame " + std::to_string(k) + " has a value that does not fit the file");
        }
      }
    }
    if (present != 0 && present != coils) {
      refuse("frame " + std::to_string(k) + " has some coils missing and some not (EST breaks are per frame)");
    }
    valid[static_cast<std::size_t>(k)] = present == coils && coils > 0;
  }
  std::string out = "EST_File Track\n";
  out += binary ? "DataType binary\n" : "DataType ascii\n";
  if (binary) out += big_endian ? "ByteOrder 10\n" : "ByteOrder 01\n";
  out += "NumFrames " + std::to_string(markers.frame_count()) + "\n";
  out += "NumChannels " + std::to_string(2 * coils) + "\n";
  // FrameShift too, so that a file of one frame (no step in its time column) keeps its rate.
  out += "FrameShift " + shortest_decimal(1 / markers.frame_rate_hz) + "\n";
  out += "EqualSpace 1\nBreaksPresent true\nCommentChar ;\n\n";
  for (Eigen::Index m = 0; m < coils; ++m) {
    const std::string& label = markers.labels[static_cast<std::size_t>(m)];
    out += "Channel_" + std::to_string(2 * m) + " " + label + "_x\n";
    out += "Channel_" + std::to_string(2 * m + 1) + " " + label + "_y\n";
  }
  out += "EST_Header_End\n";
  for (Eigen::Index k = 0; k < markers.frame_count(); ++k) {
    const double time_s = static_cast<double>(markers.first_frame + k) / markers.frame_rate_hz;
    const bool ok = valid[static_cast<std::size_t>(k)];
    if (binary) {
      put_f32(out, static_cast<float>(time_s), big_endian);
      put_f32(out, ok ? 1.0F : 0.0F, big_endian);
    } else {
      out += shortest_decimal(time_s) + (ok ? " 1" : " 0");
    }
    for (Eigen::Index m = 0; m < coils; ++m) {
      for (int i = 0; i < 2; ++i) {
        const double v = ok ? markers.positions(3 * m + i, k) * kHundredthsPerMm : 0;
        if (binary) {
          put_f32(out, static_cast<float>(v), big_endian);
        } else {
          out += " " + shortest_decimal(v);
        }
      }
    }
    if (!binary) out += "\n";
  }
  return out;
}

}  // namespace fapcast
