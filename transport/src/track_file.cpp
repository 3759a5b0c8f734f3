#include "fapcast/transport/track_file.hpp"

#include "fapcast/codec/fap_text.hpp"
#include "fapcast/fba/fba_file.hpp"
#include "fapcast/codec/json_export.hpp"
#include "fapcast/core/file_io.hpp"

#include <algorithm>
#include <stdexcept>

namespace fapcast {

std::optional<TrackFormat> track_format_of(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".fap") return TrackFormat::kFapText;
  if (ext == ".fba") return TrackFormat::kFba;
  if (ext == ".json") return TrackFormat::kJson;
  return std::nullopt;
}

FapSequence read_track_file(const std::filesystem::path& path) {
  const auto format = track_format_of(path);
  if (!format) throw std::runtime_error(path.string() + ": track-format: expected .fap, .fba or .json");
  const std::string bytes = read_file(path);
  switch (*format) {
    case TrackFormat::kFapText:
      return read_fap_text(bytes, path.string()).sequence;
    case TrackFormat::kJson:
      return read_fap_json(bytes, path.string()).sequence;
    case TrackFormat::kFba: {
      const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
      FbaDecodeResult r = decode_fba({data, bytes.size()});
      if (!r.report.ok())
        throw std::runtime_error(path.string() + ": " +
                                 (r.report.errors.empty() ? std::string("fba: corrupt stream")
                                                          : r.report.errors.front().message()));
      return std::move(r.sequence);
    }
  }
  throw std::logic_error("unreachable");
}

void write_track_file(const std::filesystem::path& path, const FapSequence& seq,
                      std::optional<std::int64_t> sample_rate) {
  const auto format = track_format_of(path);
  if (!format) throw std::runtime_error(path.string() + ": track-format: expected .fap, .fba or .json");
  switch (*format) {
    case TrackFormat::kFapText:
      write_file_atomically(path, write_fap_text(seq));
      return;
    case TrackFormat::kJson: {
      FapJsonOptions options;
      options.sample_rate = sample_rate;
      write_file_atomically(path, write_fap_json(seq, options));
      return;
    }
    case TrackFormat::kFba: {
      // fap_quant 0 is lossless but has a narrower codable range; values it refuses were received
      // as multiples of QP[fap] * the sender's fap_quant (>= 1), which fap_quant 1 codes exactly
      // with previous-value prediction (chosen predictors would predict off that grid).
      FbaEncoderOptions options;
      options.fap_quant = 0;
      std::vector<std::uint8_t> bytes;
      try {
        bytes = encode_fba(seq, options);
      } catch (const FbaEncodeError&) {
        options.fap_quant = 1;
        options.choose_predictors = false;
        bytes = encode_fba(seq, options);
      }
      write_file_atomically(path, {reinterpret_cast<const char*>(bytes.data()), bytes.size()});
      return;
    }
  }
}

}  // namespace fapcast
