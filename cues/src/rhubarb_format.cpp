#include "fapcast/cues/rhubarb_format.hpp"

#include "fapcast/core/xml_text.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>

namespace fapcast {

namespace {

// Seconds with two decimals: 0.00, 12.34.
std::string seconds(Centiseconds t) {
  const std::int64_t n = t.count();
  char buf[32];
  std::snprintf(buf, sizeof buf, "%lld.%02lld", static_cast<long long>(n / 100), static_cast<long long>(n % 100));
  return buf;
}

std::string json_string(std::string_view s) {
  std::string out = "\"";
  for (char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(u));
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string tsv(const RhubarbResult& r) {
  std::string out;
  for (const MouthCue& c : r.cues) out += seconds(c.start) + "\t" + letter(c.shape) + "\n";
  // The last line: the recording's end, the mouth closed.
  out += seconds(r.duration) + "\t" + letter(shown_shape(MouthShape::X, r.drawn)) + "\n";
  return out;
}

std::string xml(const RhubarbResult& r) {
  std::string out = "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<rhubarbResult>\n  <metadata>\n";
  out += "    <soundFile>" + escape_xml(r.sound_file) + "</soundFile>\n";
  out += "    <duration>" + seconds(r.duration) + "</duration>\n";
  out += "  </metadata>\n  <mouthCues>\n";
  for (const MouthCue& c : r.cues)
    out += "    <mouthCue start=\"" + seconds(c.start) + "\" end=\"" + seconds(c.end) + "\">" + letter(c.shape) +
           "</mouthCue>\n";
  out += "  </mouthCues>\n</rhubarbResult>\n";
  return out;
}

std::string json(const RhubarbResult& r) {
  std::string out = "{\n  \"metadata\": {\n";
  out += "    \"soundFile\": " + json_string(r.sound_file) + ",\n";
  out += "    \"duration\": " + seconds(r.duration) + "\n";
  out += "  },\n  \"mouthCues\": [\n";
  for (std::size_t i = 0; i < r.cues.size(); ++i) {
    const MouthCue& c = r.cues[i];
    out += "    { \"start\": " + seconds(c.start) + ", \"end\": " + seconds(c.end) + ", \"value\": \"" +
           letter(c.shape) + "\" }" + (i + 1 < r.cues.size() ? "," : "") + "\n";
  }
  out += "  ]\n}\n";
  return out;
}

}  // namespace

std::optional<RhubarbFormat> rhubarb_format_from_name(std::string_view name) {
  if (name == "tsv") return RhubarbFormat::kTsv;
  if (name == "xml") return RhubarbFormat::kXml;
  if (name == "json") return RhubarbFormat::kJson;
  return std::nullopt;
}

std::optional<RhubarbFormat> rhubarb_format_from_path(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  if (ext.empty()) return std::nullopt;
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return rhubarb_format_from_name(std::string_view(ext).substr(1));
}

std::string write_rhubarb(const RhubarbResult& result, RhubarbFormat format) {
  switch (format) {
    case RhubarbFormat::kTsv: return tsv(result);
    case RhubarbFormat::kXml: return xml(result);
    case RhubarbFormat::kJson: return json(result);
  }
  return {};
}

}  // namespace fapcast
