#pragma once
// Rewrites a corpus as the reference talker writes it (manifest.json, C3D markers, TextGrid
// alignments) in the other formats capture studios deliver: markers as TRC or marker CSV,
// alignments as .lab (the "phones" tier; unlabelled intervals as "sil"), optionally at a higher
// frame rate (each frame interval split into `upsample` linear steps, so resampling back to
// 60 fps gives the original frames exactly). The manifest's file names and frame rates follow.
// For the voice-build tests and the corpus-reading benchmark; SYNTHETIC data stays labelled so.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <stdexcept>
#include <string>

#include "fapcast/corpus/c3d.hpp"
#include "fapcast/corpus/lab_file.hpp"
#include "fapcast/corpus/marker_csv.hpp"
#include "fapcast/corpus/textgrid.hpp"
#include "fapcast/corpus/trc.hpp"
#include "fapcast/core/file_io.hpp"

namespace fapcast::test {

enum class MarkerFormat { c3d, trc, csv };
enum class AlignmentFormat { textgrid, lab };

inline std::string extension_of(MarkerFormat f) { return f == MarkerFormat::c3d ? ".c3d" : f == MarkerFormat::trc ? ".trc" : ".csv"; }

// `set` with `factor` - 1 linearly interpolated frames between each pair (missing if either is).
inline MarkerFrames<Millimetres> upsampled(const MarkerFrames<Millimetres>& set, int factor) {
  if (factor == 1 || set.frame_count() == 0) return set;
  const Eigen::Index frames = (set.frame_count() - 1) * factor + 1;
  MarkerFrames<Millimetres> out = MarkerFrames<Millimetres>::missing(set.marker_count(), frames);
  out.labels = set.labels;
  out.frame_rate_hz = set.frame_rate_hz * factor;
  for (Eigen::Index k = 0; k < frames; ++k) {
    const Eigen::Index i = k / factor;
    const double t = static_cast<double>(k % factor) / factor;
    for (Eigen::Index m = 0; m < set.marker_count(); ++m) {
      if (t == 0) {
        out.positions.block<3, 1>(3 * m, k) = set.at(m, i);  // NaN where missing
      } else if (set.present(m, i) && set.present(m, i + 1)) {
        out.set(m, k, (1 - t) * set.at(m, i) + t * set.at(m, i + 1));
      }
    }
  }
  return out;
}

// Writes the converted corpus of `from` into `to` (created); returns nothing, throws on trouble.
inline void convert_corpus(const std::filesystem::path& from, const std::filesystem::path& to, MarkerFormat markers,
                           AlignmentFormat alignment, int upsample = 1) {
  namespace fs = std::filesystem;
  fs::create_directories(to);
  nlohmann::json manifest = nlohmann::json::parse(read_file(from / "manifest.json"));
  const double rate = 60.0 * upsample;
  manifest["frame_rate_hz"] = rate;
  for (nlohmann::json& u : manifest["utterances"]) {
    const std::string id = u["id"];
    const std::string c3d_name = u["files"]["markers"];
    const std::string grid_name = u["files"]["alignment"];
    const C3dFile c3d = read_c3d(read_file(from / c3d_name), c3d_name);
    const MarkerFrames<Millimetres> set = upsampled(c3d.markers, upsample);
    const std::string marker_name = id + extension_of(markers);
    write_file_atomically(to / marker_name, markers == MarkerFormat::c3d   ? write_c3d(set, {c3d_synthetic_parameter()})
                                                       : markers == MarkerFormat::trc ? write_trc(set, marker_name)
                                                                                      : write_marker_csv(set));
    std::string alignment_name = grid_name;
    if (alignment == AlignmentFormat::lab) {
      const Alignment grid = read_textgrid(read_file(from / grid_name), grid_name);
      const LabelTier* phones = grid.find("phones");
      if (phones == nullptr) throw std::runtime_error(grid_name + ": no phones tier");
      LabFile lab;
      lab.unit = LabTimeUnit::seconds;
      for (Interval iv : phones->intervals) {
        if (iv.label.empty()) iv.label = "sil";
        lab.segments.push_back(iv);
      }
      alignment_name = id + ".lab";
      write_file_atomically(to / alignment_name, write_lab(lab));
    } else {
      fs::copy_file(from / grid_name, to / grid_name, fs::copy_options::overwrite_existing);
    }
    u["files"] = {{"markers", marker_name}, {"alignment", alignment_name}};
    u["frame_rate_hz"] = rate;
  }
  write_file_atomically(to / "manifest.json", manifest.dump(2) + "\n");
}

}  // namespace fapcast::test
