#include "fapcast/corpus/c3d.hpp"

#include "fapcast/core/input_error.hpp"
#include "fapcast/core/synthetic_label.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace fapcast {
namespace {

constexpr std::uint64_t kBlockBytes = 512;
constexpr std::uint8_t kParameterKey = 0x50;  // byte 2 of the header: "this is C3D"
constexpr std::uint8_t kIntel = 84;           // processor types: 83 + 1 Intel, 2 DEC, 3 MIPS
constexpr std::uint8_t kDec = 85;
constexpr std::uint8_t kMips = 86;
constexpr std::size_t kLabelsPerParameter = 255;  // a dimension is one byte

// Little-endian reads that check every range against the file size first.
class Bytes {
 public:
  Bytes(std::string_view bytes, const std::string& source) : b_(bytes), source_(source) {}
  std::uint64_t size() const { return b_.size(); }
  void need(std::uint64_t offset, std::uint64_t count, const std::string& what) const {
    if (offset > b_.size() || count > b_.size() - offset) {
      fail(std::min<std::uint64_t>(offset, b_.size()), "c3d-truncated",
           what + " (" + std::to_string(count) + " bytes at byte " + std::to_string(offset) +
               ") runs past the end of the " + std::to_string(b_.size()) + "-byte file");
    }
  }
  std::uint8_t u8(std::uint64_t at) const { return static_cast<std::uint8_t>(b_[at]); }
  std::int8_t i8(std::uint64_t at) const { return static_cast<std::int8_t>(u8(at)); }
  std::uint16_t u16(std::uint64_t at) const {
    return static_cast<std::uint16_t>(u8(at) | (u8(at + 1) << 8));
  }
  std::int16_t i16(std::uint64_t at) const { return static_cast<std::int16_t>(u16(at)); }
  float f32(std::uint64_t at) const {
    const std::uint32_t v = std::uint32_t{u8(at)} | std::uint32_t{u8(at + 1)} << 8 |
                            std::uint32_t{u8(at + 2)} << 16 | std::uint32_t{u8(at + 3)} << 24;
    return std::bit_cast<float>(v);
  }
  std::string_view text(std::uint64_t at, std::uint64_t n) const { return b_.substr(at, n); }
  [[noreturn]] void fail(std::uint64_t at, const std::string& rule, const std::string& detail) const {
    throw InputError({source_, std::nullopt, at}, rule, detail);
  }

 private:
  std::string_view b_;
  const std::string& source_;
};

struct Parameter {
  std::string group;  // upper-cased; "" if the group is not declared
  std::string name;   // upper-cased
  int type = 0;       // -1 char, 1 byte, 2 int16, 4 float32
  std::vector<std::uint64_t> dims;
  std::uint64_t elements = 1;
  std::uint64_t data_at = 0;  // file offset of the values
  std::uint64_t entry_at = 0;
};

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

std::string_view trim_padding(std::string_view s) {
  while (!s.empty() && (s.back() == ' ' || s.back() == '\0')) s.remove_suffix(1);
  return s;
}

class ParameterSection {
 public:
  // Walks the entries in [start + 4, end); each must lie inside that range.
  ParameterSection(const Bytes& file, std::uint64_t start, std::uint64_t end) : file_(file) {
    std::vector<std::pair<int, std::string>> groups;
    std::vector<std::pair<int, Parameter>> params;
    std::uint64_t pos = start + 4;
    while (pos + 2 <= end) {
      const int nchars = file.i8(pos);
      const int id = file.i8(pos + 1);
      if (nchars == 0 || id == 0) break;  // the end of the entries
      const std::uint64_t len = static_cast<std::uint64_t>(std::abs(nchars));
      const std::uint64_t next_field = pos + 2 + len;
      if (next_field + 2 > end) bad(pos, "entry's name runs past the parameter section");
      const std::string name = upper(file.text(pos + 2, len));
      const int next = file.i16(next_field);
      const std::uint64_t body = next_field + 2;
      if (id < 0) {
        groups.emplace_back(-id, name);
      } else {
        Parameter p;
        p.name = name;
        p.entry_at = pos;
        if (body + 2 > end) bad(pos, "parameter " + name + " runs past the parameter section");
        p.type = file.i8(body);
        if (p.type != -1 && p.type != 1 && p.type != 2 && p.type != 4) {
          bad(body, "parameter " + name + " has data type " + std::to_string(p.type) +
                        " (not -1, 1, 2 or 4)");
        }
        const std::uint64_t ndims = file.u8(body + 1);
        if (body + 2 + ndims > end) bad(pos, "parameter " + name + "'s dimensions run past the section");
        for (std::uint64_t d = 0; d < ndims; ++d) {
          p.dims.push_back(file.u8(body + 2 + d));
          p.elements *= p.dims.back();
          // Bounded by the section size: stop multiplying once it cannot fit anyway.
          if (p.elements > end) bad(pos, "parameter " + name + " is larger than the parameter section");
        }
        p.data_at = body + 2 + ndims;
        const std::uint64_t data_bytes = p.elements * static_cast<std::uint64_t>(std::abs(p.type));
        if (p.data_at + data_bytes > end) bad(pos, "parameter " + name + "'s values run past the section");
        params.emplace_back(id, std::move(p));
      }
      if (next == 0) break;  // the last entry
      if (next < 0) bad(next_field, "entry " + name + " has a negative offset to the next entry");
      pos = next_field + static_cast<std::uint64_t>(next);
    }
    for (auto& [id, p] : params) {
      for (const auto& [gid, gname] : groups) {
        if (gid == id) p.group = gname;
      }
      params_.push_back(std::move(p));
    }
  }

  const Parameter* find(std::string_view group, std::string_view name) const {
    for (const Parameter& p : params_) {
      if (p.group == group && p.name == name) return &p;
    }
    return nullptr;
  }
  const std::vector<Parameter>& all() const { return params_; }

  // The first value of a numeric parameter as a non-negative integer (int16 read as unsigned,
  // as files with more than 32767 points or frames need).
  std::uint64_t count(const Parameter& p) const {
    require_value(p);
    if (p.type == 1) return file_.u8(p.data_at);
    if (p.type == 2) return file_.u16(p.data_at);
    if (p.type != 4) bad(p.entry_at, p.group + ":" + p.name + " is text, not a count");
    const float v = file_.f32(p.data_at);  // type 4 with >= 1 element: 4 bytes in the section
    if (!(v >= 0 && v <= 65535) || v != std::floor(v)) {
      bad(p.entry_at, p.group + ":" + p.name + " is not a count");
    }
    return static_cast<std::uint64_t>(v);
  }
  double real(const Parameter& p) const {
    require_value(p);
    if (p.type == 4) return file_.f32(p.data_at);
    if (p.type == 2) return file_.i16(p.data_at);
    if (p.type == 1) return file_.u8(p.data_at);
    bad(p.entry_at, p.group + ":" + p.name + " is text, not a number");
  }
  // A character parameter's strings: one per row of its first dimension, padding trimmed.
  std::vector<std::string> strings(const Parameter& p) const {
    if (p.type != -1) bad(p.entry_at, p.group + ":" + p.name + " is not text");
    const std::uint64_t row = p.dims.empty() ? 1 : p.dims[0];
    std::vector<std::string> out;
    if (row == 0) return out;
    for (std::uint64_t at = 0; at + row <= p.elements; at += row) {
      out.emplace_back(trim_padding(file_.text(p.data_at + at, row)));
    }
    return out;
  }

 private:
  void require_value(const Parameter& p) const {
    if (p.elements == 0) bad(p.entry_at, p.group + ":" + p.name + " has no value");
  }
  [[noreturn]] void bad(std::uint64_t at, const std::string& detail) const {
    file_.fail(at, "c3d-bad-parameter", detail);
  }
  const Bytes& file_;
  std::vector<Parameter> params_;
};

// ---- writing -------------------------------------------------------------------------------

void put_u8(std::string& out, unsigned v) { out += static_cast<char>(v & 0xFF); }
void put_u16(std::string& out, unsigned v) {
  put_u8(out, v);
  put_u8(out, v >> 8);
}
void put_f32(std::string& out, float v) {
  const auto bits = std::bit_cast<std::uint32_t>(v);
  for (int k = 0; k < 4; ++k) put_u8(out, bits >> (8 * k));
}

bool valid_name(std::string_view s) {
  return !s.empty() && s.size() <= 32 && std::all_of(s.begin(), s.end(), [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
  });
}

class SectionWriter {
 public:
  void group(int id, std::string_view name, std::string_view description) {
    std::string body;
    put_u8(body, static_cast<unsigned>(description.size()));
    body += description;
    entry(-id, name, body);
  }
  void int16(int group, std::string_view name, unsigned value) {
    std::string data;
    put_u16(data, value);
    parameter(group, name, 2, {}, data);
  }
  void float32(int group, std::string_view name, float value) {
    std::string data;
    put_f32(data, value);
    parameter(group, name, 4, {}, data);
  }
  // Rows padded with spaces to the longest (at least 1 byte wide).
  void text(int group, std::string_view name, const std::vector<std::string>& rows, bool two_d,
            std::string_view description = "") {
    std::size_t width = 1;
    for (const std::string& r : rows) width = std::max(width, r.size());
    std::string data;
    for (const std::string& r : rows) data += r + std::string(width - r.size(), ' ');
    std::vector<unsigned> dims{static_cast<unsigned>(width)};
    if (two_d) dims.push_back(static_cast<unsigned>(rows.size()));
    if (!two_d && !rows.empty()) dims[0] = static_cast<unsigned>(rows[0].size());
    if (!two_d && !rows.empty()) data = rows[0];
    parameter(group, name, -1, dims, data, description);
  }
  std::string finish() {
    if (last_next_ != std::string::npos) out_[last_next_] = out_[last_next_ + 1] = 0;  // last entry
    return std::move(out_);
  }

 private:
  void parameter(int group, std::string_view name, int type, const std::vector<unsigned>& dims,
                 const std::string& data, std::string_view description = "") {
    std::string body;
    put_u8(body, static_cast<unsigned>(type));
    put_u8(body, static_cast<unsigned>(dims.size()));
    for (unsigned d : dims) put_u8(body, d);
    body += data;
    put_u8(body, static_cast<unsigned>(description.size()));
    body += description;
    entry(group, name, body);
  }
  void entry(int id, std::string_view name, const std::string& body) {
    put_u8(out_, static_cast<unsigned>(name.size()));
    put_u8(out_, static_cast<unsigned>(id));
    out_ += name;
    last_next_ = out_.size();
    put_u16(out_, static_cast<unsigned>(2 + body.size()));  // from this field to the next entry
    out_ += body;
  }
  std::string out_;
  std::size_t last_next_ = std::string::npos;
};

// How many groups `extra` declares (each needs a one-byte id).
std::size_t groups_needed(const std::vector<C3dTextParameter>& extra) {
  std::vector<std::string_view> seen;
  for (const C3dTextParameter& p : extra) {
    if (std::find(seen.begin(), seen.end(), p.group) == seen.end()) seen.push_back(p.group);
  }
  return seen.size();
}

[[noreturn]] void refuse(const std::string& why) { throw std::invalid_argument("write_c3d: " + why); }

}  // namespace

C3dFile read_c3d(std::string_view bytes, const std::string& source) {
  const Bytes file(bytes, source);
  file.need(0, kBlockBytes, "the header block");
  if (file.u8(1) != kParameterKey) {
    file.fail(1, "c3d-bad-key", "header byte 2 is " + std::to_string(file.u8(1)) + ", not 80 (0x50): not a C3D file");
  }
  const std::uint64_t parameter_block = file.u8(0);
  if (parameter_block < 2) file.fail(0, "c3d-layout", "the parameter section must start at block 2 or later");
  const std::uint64_t section = (parameter_block - 1) * kBlockBytes;
  file.need(section, 4, "the parameter section header");
  const std::uint8_t processor = file.u8(section + 3);
  if (processor == kDec || processor == kMips) {
    file.fail(section + 3, "c3d-processor-unsupported",
              std::string(processor == kDec ? "DEC (VAX)" : "MIPS (SGI, big-endian)") +
                  " files are not supported; convert to Intel (processor type 84)");
  }
  if (processor != kIntel) {
    file.fail(section + 3, "c3d-bad-processor", "processor type " + std::to_string(processor) +
                                                    " is not 84, 85 or 86");
  }
  const std::uint64_t section_blocks = file.u8(section + 2);
  if (section_blocks == 0) file.fail(section + 2, "c3d-layout", "the parameter section has 0 blocks");
  file.need(section, section_blocks * kBlockBytes, "the parameter section");
  const std::uint64_t section_end = section + section_blocks * kBlockBytes;
  const ParameterSection params(file, section, section_end);

  auto count_or = [&](std::string_view group, std::string_view name, std::uint64_t fallback) {
    const Parameter* p = params.find(group, name);
    return p ? params.count(*p) : fallback;
  };
  auto real_or = [&](std::string_view group, std::string_view name, double fallback) {
    const Parameter* p = params.find(group, name);
    return p ? params.real(*p) : fallback;
  };

  const std::uint64_t points = file.u16(2);
  if (count_or("POINT", "USED", points) != points) {
    file.fail(2, "c3d-count-mismatch", "header says " + std::to_string(points) + " points, POINT:USED " +
                                           std::to_string(count_or("POINT", "USED", points)));
  }
  const std::uint64_t data_block = file.u16(16);
  if (count_or("POINT", "DATA_START", data_block) != data_block) {
    file.fail(16, "c3d-count-mismatch", "header says data starts at block " + std::to_string(data_block) +
                                            ", POINT:DATA_START " +
                                            std::to_string(count_or("POINT", "DATA_START", data_block)));
  }
  if (data_block < 2 || (data_block - 1) * kBlockBytes < section_end) {
    file.fail(16, "c3d-layout", "data block " + std::to_string(data_block) + " overlaps the header or parameters");
  }
  const double scale = real_or("POINT", "SCALE", file.f32(12));
  if (!std::isfinite(scale) || scale == 0) {
    file.fail(12, "c3d-bad-scale", "POINT:SCALE must be finite and non-zero");
  }
  const double rate_hz = real_or("POINT", "RATE", file.f32(20));
  if (!std::isfinite(rate_hz) || rate_hz <= 0) file.fail(20, "c3d-bad-rate", "POINT:RATE must be positive");
  const std::uint64_t first = file.u16(6);
  const std::uint64_t last = file.u16(8);
  if (last + 1 < first) {
    file.fail(8, "c3d-frame-range", "last frame " + std::to_string(last) + " is before first frame " +
                                        std::to_string(first));
  }
  const std::uint64_t frames = last + 1 - first;

  // Analog samples follow each frame's points: ANALOG:USED channels x (analog rate / point rate).
  std::uint64_t analog = file.u16(4);
  if (const Parameter* used = params.find("ANALOG", "USED"); used && params.count(*used) > 0) {
    const double ratio = real_or("ANALOG", "RATE", 0) / rate_hz;
    if (!(ratio >= 1 && ratio <= 65535) || ratio != std::round(ratio)) {
      file.fail(used->entry_at, "c3d-analog-rate",
                "ANALOG:RATE is not a whole multiple (1 to 65535) of POINT:RATE");
    }
    const std::uint64_t from_parameters = params.count(*used) * static_cast<std::uint64_t>(ratio);
    if (from_parameters != analog) {
      file.fail(4, "c3d-count-mismatch", "header says " + std::to_string(analog) +
                                             " analog samples per frame, ANALOG parameters " +
                                             std::to_string(from_parameters));
    }
  }

  const bool floats = scale < 0;
  const std::uint64_t word = floats ? 4 : 2;
  const std::uint64_t frame_bytes = (points * 4 + analog) * word;
  const std::uint64_t data_at = (data_block - 1) * kBlockBytes;
  file.need(data_at, frames * frame_bytes, "the point and analog data of " + std::to_string(frames) + " frames");

  C3dFile out;
  out.float_storage = floats;
  out.point_scale = scale;
  for (const Parameter& p : params.all()) {
    if (p.type != -1 || p.group.empty()) continue;
    std::string joined;
    for (const std::string& s : params.strings(p)) joined += (joined.empty() ? "" : "\n") + s;
    out.text_parameters[p.group + ":" + p.name] = joined;
  }
  if (const Parameter* u = params.find("POINT", "UNITS")) {
    const auto units = params.strings(*u);
    if (!units.empty()) out.units = units[0];
  }
  const std::optional<double> mm_per_unit = millimetres_per_unit(out.units);
  if (!mm_per_unit) {
    file.fail(params.find("POINT", "UNITS")->entry_at, "c3d-units",
              "POINT:UNITS \"" + out.units + "\" is not mm, cm, m or in");
  }

  MarkerFrames<Millimetres>& m = out.markers;
  m = MarkerFrames<Millimetres>::missing(static_cast<Eigen::Index>(points), static_cast<Eigen::Index>(frames));
  m.frame_rate_hz = rate_hz;
  m.first_frame = static_cast<std::int64_t>(first);
  std::size_t labelled = 0;
  for (int k = 1; labelled < points; ++k) {  // POINT:LABELS, LABELS2, LABELS3 ...
    const Parameter* p = params.find("POINT", k == 1 ? "LABELS" : "LABELS" + std::to_string(k));
    if (!p) break;
    for (std::string& label : params.strings(*p)) {
      if (labelled < points) m.labels[labelled++] = std::move(label);
    }
  }
  for (std::size_t i = 0; i < points; ++i) {
    if (m.labels[i].empty()) m.labels[i] = "*" + std::to_string(i + 1);
  }

  const double to_mm = (floats ? 1.0 : scale) * *mm_per_unit;
  const unsigned char* data = reinterpret_cast<const unsigned char*>(bytes.data()) + data_at;
  for (std::uint64_t f = 0; f < frames; ++f) {
    const unsigned char* frame = data + f * frame_bytes;
    for (std::uint64_t p = 0; p < points; ++p) {
      const unsigned char* s = frame + p * 4 * word;
      const auto fi = static_cast<Eigen::Index>(f);
      const auto pi = static_cast<Eigen::Index>(p);
      double xyz[3];
      bool missing = false;
      if (floats) {
        float v[4];
        std::memcpy(v, s, sizeof v);  // Intel order = host order on the supported hosts
        for (int k = 0; k < 3; ++k) xyz[k] = v[k];
        missing = v[3] < 0;
      } else {
        std::int16_t v[4];
        std::memcpy(v, s, sizeof v);
        for (int k = 0; k < 3; ++k) xyz[k] = v[k];
        missing = v[3] < 0;
      }
      if (missing) continue;  // stays NaN
      for (int k = 0; k < 3; ++k) {
        if (!std::isfinite(xyz[k])) {
          file.fail(data_at + f * frame_bytes + p * 4 * word, "c3d-bad-sample",
                    "frame " + std::to_string(f + first) + " point " + std::to_string(p + 1) +
                        " is not finite");
        }
        m.positions(3 * pi + k, fi) = xyz[k] * to_mm;
      }
    }
  }
  return out;
}

std::string write_c3d(const MarkerFrames<Millimetres>& markers, const std::vector<C3dTextParameter>& extra) {
  if (!markers.consistent()) refuse("positions and labels disagree in shape");
  const auto frames = static_cast<std::uint64_t>(markers.frame_count());
  const auto points = static_cast<std::uint64_t>(markers.marker_count());
  if (frames > 65535 || points > 65535) refuse("more than 65535 frames or markers");
  if (!(markers.frame_rate_hz > 0) || !std::isfinite(static_cast<float>(markers.frame_rate_hz))) {
    refuse("frame rate must be positive and fit a float");
  }
  for (const std::string& label : markers.labels) {
    if (label.empty() || label.size() > 255 || label.back() == ' ' || label.find('\0') != std::string::npos) {
      refuse("label \"" + label + "\" is empty, longer than 255 bytes or ends in a space");
    }
  }

  // Float storage: every present coordinate must fit a float32 (an integer-storage file read
  // with a huge POINT:SCALE may not).
  for (Eigen::Index f = 0; f < markers.frame_count(); ++f) {
    for (Eigen::Index c = 0; c < markers.positions.rows(); ++c) {
      if (markers.present(c / 3, f) && !std::isfinite(static_cast<float>(markers.positions(c, f)))) {
        refuse("frame " + std::to_string(f) + " has a coordinate that does not fit a float");
      }
    }
  }
  for (const C3dTextParameter& p : extra) {
    if (!valid_name(p.group) || !valid_name(p.name) || p.group == "POINT" || p.group == "ANALOG") {
      refuse("parameter " + p.group + ":" + p.name + " needs names of A-Z 0-9 _ outside POINT and ANALOG");
    }
    if (p.value.size() > 255 || p.description.size() > 255) {
      refuse(p.group + ":" + p.name + " is longer than 255 bytes");
    }
  }
  // The section's size does not depend on DATA_START's value: build once to measure, once to keep.
  auto build_section = [&](unsigned data_block) {
    SectionWriter section;
    section.group(1, "POINT", "3-D point parameters");
    section.group(2, "ANALOG", "analog data parameters");
    section.int16(1, "USED", static_cast<unsigned>(points));
    section.int16(1, "FRAMES", static_cast<unsigned>(frames));
    section.int16(1, "DATA_START", data_block);
    section.float32(1, "SCALE", -1.0F);
    section.float32(1, "RATE", static_cast<float>(markers.frame_rate_hz));
    section.text(1, "UNITS", {"mm"}, false);
    // LABELS, LABELS2 ...: at most 255 per parameter and at most 32000 bytes per entry.
    std::size_t width = 1;
    for (const std::string& label : markers.labels) width = std::max(width, label.size());
    const std::size_t per = std::min(kLabelsPerParameter, std::size_t{32000} / width);
    for (std::size_t start = 0, k = 1;; start += per, ++k) {
      const auto end = std::min<std::size_t>(start + per, points);
      const std::vector<std::string> chunk(markers.labels.begin() + static_cast<std::ptrdiff_t>(start),
                                           markers.labels.begin() + static_cast<std::ptrdiff_t>(end));
      section.text(1, k == 1 ? "LABELS" : "LABELS" + std::to_string(k), chunk, true);
      if (end >= points) break;
    }
    section.int16(2, "USED", 0);
    section.float32(2, "RATE", static_cast<float>(markers.frame_rate_hz));
    std::vector<std::string> groups;
    for (const C3dTextParameter& p : extra) {
      auto g = std::find(groups.begin(), groups.end(), p.group);
      if (g == groups.end()) {
        groups.push_back(p.group);
        section.group(static_cast<int>(groups.size()) + 2, p.group, "");
        g = groups.end() - 1;
      }
      section.text(static_cast<int>(g - groups.begin()) + 3, p.name, {p.value}, false, p.description);
    }
    return section.finish();
  };
  const std::uint64_t section_blocks = (4 + build_section(0).size() + kBlockBytes - 1) / kBlockBytes;
  if (section_blocks > 250 || 2 + groups_needed(extra) > 127) refuse("too many parameters for C3D");
  const auto data_block = static_cast<unsigned>(2 + section_blocks);

  std::string out;
  out.reserve((data_block - 1) * kBlockBytes + frames * points * 16);
  // Header block (16-bit words, 1-based as the C3D manual counts them).
  put_u8(out, 2);              // word 1: parameter section at block 2 ...
  put_u8(out, kParameterKey);  // ... and the C3D key
  put_u16(out, static_cast<unsigned>(points));  // word 2
  put_u16(out, 0);                              // word 3: analog samples per frame, all channels
  put_u16(out, 1);                              // word 4: first frame
  put_u16(out, static_cast<unsigned>(frames));  // word 5: last frame
  put_u16(out, 0);                              // word 6: maximum interpolation gap
  put_f32(out, -1.0F);                          // words 7-8: scale; negative = float storage
  put_u16(out, data_block);                     // word 9
  put_u16(out, 0);                              // word 10: analog samples per frame, one channel
  put_f32(out, static_cast<float>(markers.frame_rate_hz));  // words 11-12
  out.resize(kBlockBytes, '\0');               // words 13-256: reserved, no events
  // Parameter section.
  put_u8(out, 1);
  put_u8(out, kParameterKey);
  put_u8(out, static_cast<unsigned>(section_blocks));
  put_u8(out, kIntel);
  out += build_section(data_block);
  out.resize((data_block - 1) * kBlockBytes, '\0');
  // Points: X Y Z residual as float32; a missing sample is 0 0 0 with residual -1.
  for (Eigen::Index f = 0; f < markers.frame_count(); ++f) {
    for (Eigen::Index p = 0; p < markers.marker_count(); ++p) {
      const bool missing = !markers.present(p, f);
      for (int k = 0; k < 3; ++k) {
        put_f32(out, missing ? 0.0F : static_cast<float>(markers.positions(3 * p + k, f)));
      }
      put_f32(out, missing ? -1.0F : 0.0F);
    }
  }
  out.resize((out.size() + kBlockBytes - 1) / kBlockBytes * kBlockBytes, '\0');
  return out;
}

C3dTextParameter c3d_synthetic_parameter() {
  return {"FAPCAST", "SYNTHETIC", std::string(kSyntheticLabel), "written by the fapcast reference talker"};
}

}  // namespace fapcast
