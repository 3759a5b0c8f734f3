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

TrackFileBytes track_file_bytes(const std::filesystem::path& path, const FapSequence& seq,
                                const TrackWriteOptions& options) {
  const auto format = track_format_of(path);
  if (!format) throw std::runtime_error(path.string() + ": track-format: expected .fap, .fba or .json");
  switch (*format) {
    case TrackFormat::kFapText: {
      TrackFileBytes out;
      try {
        out.bytes = write_fap_text(seq, options.fap);
      } catch (const std::invalid_argument& e) {
        throw std::runtime_error(path.string() + ": " + e.what());
      }
      out.notes = fap_text_player_notes(seq, options.fap);
      return out;
    }
    case TrackFormat::kJson: {
      FapJsonOptions json;
      json.sample_rate = options.sample_rate;
      return {write_fap_json(seq, json), {}};
    }
    case TrackFormat::kFba: {
      // Lossless: the standard syntax at fap_quant 0 where it reaches every value, else the
      // fapcast profile (which standard decoders refuse at its first bytes).
      FbaEncoderOptions fba;
      fba.fap_quant = 0;
      std::vector<std::string> notes;
      if (const auto refusal = fba_standard_refusal(seq, 0)) {
        fba.profile = FbaProfile::kFapcast;
        notes.push_back("written in the fapcast profile (lossless), which standard FBA decoders refuse: the standard "
                        "syntax cannot code " + *refusal);
      } else {
        notes.push_back("standard FBA at fap_quant 0 (lossless)");
      }
      const std::vector<std::uint8_t> bytes = encode_fba(seq, fba);
      return {{reinterpret_cast<const char*>(bytes.data()), bytes.size()}, std::move(notes)};
    }
  }
  throw std::logic_error("unreachable");
}

std::vector<std::string> write_track_file(const std::filesystem::path& path, const FapSequence& seq,
                                          const TrackWriteOptions& options) {
  TrackFileBytes out = track_file_bytes(path, seq, options);
  write_file_atomically(path, out.bytes);
  return std::move(out.notes);
}

}  // namespace fapcast
