#include "fapcast/synth/voice_corpus.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>

#include "fapcast/synth/c3d.hpp"
#include "fapcast/synth/head_pose.hpp"
#include "fapcast/synth/input_error.hpp"
#include "fapcast/synth/marker_map.hpp"
#include "fapcast/synth/textgrid.hpp"

namespace fapcast::synth {
namespace fs = std::filesystem;
namespace {

[[noreturn]] void refuse(const fs::path& file, const std::string& rule, const std::string& detail) {
  throw InputError({file.string(), std::nullopt, std::nullopt}, rule, detail);
}

std::string slurp(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) refuse(file, "corpus-file-missing", "cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  return std::move(text).str();
}

std::string json_string(const nlohmann::json& object, const char* key, const fs::path& manifest,
                        const std::string& where) {
  const auto it = object.find(key);
  if (it == object.end() || !it->is_string() || it->get<std::string>().empty())
    refuse(manifest, "corpus-manifest", where + ": \"" + key + "\" must be a non-empty string");
  return it->get<std::string>();
}

// A manifest path: relative, inside the corpus directory.
fs::path corpus_file(const fs::path& directory, const std::string& name, const fs::path& manifest,
                     const std::string& where) {
  const fs::path relative(name);
  if (relative.is_absolute() || std::any_of(relative.begin(), relative.end(), [](const fs::path& p) { return p == ".."; }))
    refuse(manifest, "corpus-manifest", where + ": \"" + name + "\" must be a relative path inside the corpus");
  const fs::path path = directory / relative;
  if (!fs::is_regular_file(path)) refuse(path, "corpus-file-missing", "listed by " + where + " but not there");
  return path;
}

CorpusListing read_manifest(const fs::path& directory, const fs::path& manifest) {
  const nlohmann::json j = nlohmann::json::parse(slurp(manifest), nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded() || !j.is_object()) refuse(manifest, "corpus-manifest", "not a JSON object");
  CorpusListing listing;
  listing.directory = directory;
  if (const auto it = j.find("synthetic"); it != j.end()) {
    if (!it->is_boolean()) refuse(manifest, "corpus-manifest", "\"synthetic\" must be true or false");
    listing.synthetic = it->get<bool>();
  }
  if (const auto it = j.find("provenance"); it != j.end() && it->is_string()) listing.label = it->get<std::string>();
  if (const auto it = j.find("seed"); it != j.end() && it->is_number_unsigned()) listing.seed = it->get<std::uint64_t>();
  if (const auto it = j.find("frame_rate_hz"); it != j.end() && (!it->is_number() || it->get<double>() != kVoiceFramesPerSecond))
    refuse(manifest, "corpus-manifest", "\"frame_rate_hz\" must be 60 (the voice build does not resample)");
  if (const auto it = j.find("marker_map"); it != j.end()) {
    if (!it->is_object()) refuse(manifest, "corpus-manifest", "\"marker_map\" must be an object");
    for (const auto& [from, to] : it->items()) {
      if (!to.is_string()) refuse(manifest, "corpus-manifest", "marker_map \"" + from + "\" must map to a string");
      listing.marker_map[from] = to.get<std::string>();
    }
  }
  const auto utterances = j.find("utterances");
  if (utterances == j.end() || !utterances->is_array())
    refuse(manifest, "corpus-manifest", "\"utterances\" must be an array");
  std::set<std::string> ids;
  for (std::size_t i = 0; i < utterances->size(); ++i) {
    const nlohmann::json& u = (*utterances)[i];
    const std::string where = "utterances[" + std::to_string(i) + "]";
    if (!u.is_object()) refuse(manifest, "corpus-manifest", where + " must be an object");
    CorpusUtterance entry;
    entry.id = json_string(u, "id", manifest, where);
    if (!ids.insert(entry.id).second) refuse(manifest, "corpus-manifest", where + ": id \"" + entry.id + "\" repeats");
    const auto files = u.find("files");
    if (files == u.end() || !files->is_object()) refuse(manifest, "corpus-manifest", where + ": \"files\" must be an object");
    entry.markers = corpus_file(directory, json_string(*files, "markers", manifest, where + ".files"), manifest, where);
    entry.alignment = corpus_file(directory, json_string(*files, "alignment", manifest, where + ".files"), manifest, where);
    if (const auto rate = u.find("frame_rate_hz"); rate != u.end() && (!rate->is_number() || rate->get<double>() != kVoiceFramesPerSecond))
      refuse(manifest, "corpus-manifest", where + ": \"frame_rate_hz\" must be 60");
    listing.utterances.push_back(std::move(entry));
  }
  return listing;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

Phone phone_of(const std::string& label, const fs::path& file, std::size_t interval) {
  const std::string l = lower(label);
  if (l.empty() || l == "sil" || l == "sp" || l == "pau") return Phone::SIL;
  try {
    return parse_arpabet(label, file.string()).phone;
  } catch (const std::invalid_argument&) {
    refuse(file, "corpus-alignment", "phones interval " + std::to_string(interval + 1) + ": \"" + label +
                                         "\" is not an ARPAbet phone");
  }
}

}  // namespace

CorpusListing list_corpus(const fs::path& directory) {
  if (!fs::is_directory(directory)) refuse(directory, "corpus-missing", "not a directory");
  CorpusListing listing;
  if (const fs::path manifest = directory / "manifest.json"; fs::exists(manifest)) {
    listing = read_manifest(directory, manifest);
  } else {
    listing.directory = directory;
    std::vector<fs::path> c3ds;
    for (const auto& entry : fs::directory_iterator(directory))
      if (entry.is_regular_file() && lower(entry.path().extension().string()) == ".c3d") c3ds.push_back(entry.path());
    std::sort(c3ds.begin(), c3ds.end());
    for (const fs::path& c3d : c3ds) {
      fs::path grid = c3d;
      grid.replace_extension(".TextGrid");
      if (!fs::is_regular_file(grid)) refuse(grid, "corpus-file-missing", "no TextGrid beside " + c3d.filename().string());
      listing.utterances.push_back({c3d.stem().string(), c3d, grid});
    }
  }
  if (listing.utterances.empty())
    refuse(directory, "corpus-empty", "no utterance (manifest.json lists none, or no *.c3d with a *.TextGrid)");
  return listing;
}

CorpusTake read_corpus_take(const CorpusListing& listing, std::size_t index) {
  const CorpusUtterance& u = listing.utterances.at(index);
  CorpusTake take;
  take.id = u.id;
  const C3dFile c3d = read_c3d(slurp(u.markers), u.markers.string());
  const MarkerSet& set = c3d.markers;
  if (set.frame_rate_hz != kVoiceFramesPerSecond)
    refuse(u.markers, "corpus-frame-rate", "POINT:RATE is " + std::to_string(set.frame_rate_hz) + " Hz, the voice build needs 60");
  const auto sites = marker_sites();
  const Eigen::Index frames = set.frame_count();
  MarkerFrames& m = take.markers;
  m.frame_rate_hz = kVoiceFramesPerSecond;
  m.positions_cm = Eigen::MatrixXd::Constant(3 * static_cast<Eigen::Index>(sites.size()), frames, std::nan(""));
  for (const auto& site : sites) m.labels.emplace_back(site.label);
  std::vector<bool> found(sites.size(), false);
  for (Eigen::Index k = 0; k < set.marker_count(); ++k) {
    const std::string& label = set.labels[static_cast<std::size_t>(k)];
    std::string site_label = label;
    if (const auto it = listing.marker_map.find(label); it != listing.marker_map.end() && it->second != "rigid")
      site_label = it->second;
    if (site_label == "ignore") continue;
    const auto row = std::find_if(sites.begin(), sites.end(), [&](const MarkerSite& s) { return s.label == site_label; });
    if (row == sites.end() || found[static_cast<std::size_t>(row - sites.begin())]) continue;
    const auto r = static_cast<Eigen::Index>(row - sites.begin());
    found[static_cast<std::size_t>(r)] = true;
    for (Eigen::Index f = 0; f < frames; ++f)
      if (!set.missing(f, k)) m.positions_cm.block<3, 1>(3 * r, f) = set.position(f, k) / 10.0;
  }
  for (std::size_t r = 0; r < sites.size(); ++r)
    if (!found[r]) refuse(u.markers, "corpus-markers", "no marker for site " + std::string(sites[r].label) +
                                                           " (label it so, or map a label to it in manifest.json's marker_map)");

  const Alignment alignment = read_textgrid(slurp(u.alignment), u.alignment.string());
  const LabelTier* phones = alignment.find("phones");
  if (phones == nullptr || phones->kind != TierKind::intervals)
    refuse(u.alignment, "corpus-alignment", "no interval tier named \"phones\"");
  const std::int64_t aligned = to_sample(alignment.end_s, kVoiceFramesPerSecond);
  if (std::llabs(aligned - frames) > kMaxLengthMismatchFrames)
    refuse(u.alignment, "corpus-length", "the alignment ends at frame " + std::to_string(aligned) + " (" +
                                             std::to_string(alignment.end_s) + " s), " + u.markers.filename().string() +
                                             " has " + std::to_string(frames) + " frames");
  for (std::size_t i = 0; i < phones->intervals.size(); ++i) {
    const Interval& iv = phones->intervals[i];
    const Phone p = phone_of(iv.label, u.alignment, i);
    const auto clamp = [&](double t) { return std::clamp<std::int64_t>(to_sample(t, kVoiceFramesPerSecond), 0, frames); };
    const std::int64_t first = clamp(iv.start_s);
    const std::int64_t end = clamp(iv.end_s);
    if (end <= first) continue;
    if (!take.phones.empty() && p == Phone::SIL && take.phones.back() == Phone::SIL &&
        take.spans.back().first + take.spans.back().count == first) {
      take.spans.back().count += static_cast<std::uint32_t>(end - first);
      continue;
    }
    take.phones.push_back(p);
    take.spans.push_back({static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(end - first)});
  }
  take.synthetic = c3d.text_parameters.count("FAPCAST:SYNTHETIC") > 0 || is_synthetic(alignment);
  if (take.phones.empty()) refuse(u.alignment, "corpus-alignment", "the phones tier has no interval of a frame or more");
  return take;
}

std::vector<std::size_t> source_marker_rows() {
  std::vector<std::size_t> rows;
  const auto sites = marker_sites();
  for (std::size_t r = 0; r < sites.size(); ++r)
    if (sites[r].role != MarkerRole::rigid) rows.push_back(r);
  return rows;
}

Eigen::Matrix3Xd corpus_rigid_reference(const CorpusTake& take, const std::string& source) {
  const auto rigid = rigid_marker_rows();
  for (Eigen::Index f = 0; f < take.markers.frame_count(); ++f) {
    bool all = true;
    for (std::size_t r : rigid) all = all && take.markers.present(static_cast<Eigen::Index>(r), f);
    if (all) return rigid_reference(take.markers, rigid, f);
  }
  refuse(source, "corpus-markers", "no frame has all " + std::to_string(rigid.size()) +
                                       " rigid head markers: the head pose cannot be referenced");
}

Eigen::MatrixXd source_vectors_m(const MarkerFrames& stabilised, const std::string& source) {
  const auto rows = source_marker_rows();
  const Eigen::Index frames = stabilised.frame_count();
  Eigen::MatrixXd out(3 * static_cast<Eigen::Index>(rows.size()), frames);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto m = static_cast<Eigen::Index>(rows[i]);
    std::vector<Eigen::Index> present;
    for (Eigen::Index f = 0; f < frames; ++f)
      if (stabilised.present(m, f)) present.push_back(f);
    if (present.empty())
      refuse(source, "corpus-markers", "feature point " + stabilised.labels[rows[i]] + " is missing in every frame");
    // Linear in time between the present samples around a gap, held beyond the first / last.
    std::size_t next = 0;
    for (Eigen::Index f = 0; f < frames; ++f) {
      while (next < present.size() && present[next] < f) ++next;
      Eigen::Vector3d p;
      if (next < present.size() && present[next] == f) {
        p = stabilised.at(m, f);
      } else if (next == 0) {
        p = stabilised.at(m, present.front());
      } else if (next == present.size()) {
        p = stabilised.at(m, present.back());
      } else {
        const Eigen::Index a = present[next - 1], b = present[next];
        const double t = static_cast<double>(f - a) / static_cast<double>(b - a);
        p = (1 - t) * stabilised.at(m, a) + t * stabilised.at(m, b);
      }
      out.block<3, 1>(3 * static_cast<Eigen::Index>(i), f) = p / 100.0;
    }
  }
  return out;
}

}  // namespace fapcast::synth
