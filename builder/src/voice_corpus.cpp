#include "fapcast/builder/voice_corpus.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <stdexcept>

#include "fapcast/corpus/c3d.hpp"
#include "fapcast/capture/head_pose.hpp"
#include "fapcast/core/input_error.hpp"
#include "fapcast/corpus/lab_file.hpp"
#include "fapcast/corpus/label_tier.hpp"
#include "fapcast/corpus/marker_csv.hpp"
#include "fapcast/face/marker_map.hpp"
#include "fapcast/capture/marker_resample.hpp"
#include "fapcast/phonetics/phone_map.hpp"
#include "fapcast/corpus/textgrid.hpp"
#include "fapcast/corpus/trc.hpp"
#include "fapcast/core/text_input.hpp"
#include "fapcast/core/wav_file.hpp"
#include "fapcast/phonetics/phone.hpp"
#include "fapcast/phonetics/timed_phone.hpp"
#include "fapcast/recognise/speech_aligner.hpp"

namespace fapcast {
namespace fs = std::filesystem;
namespace {

// The 60 fps capture grid as a clock: to_sample at it gives frame numbers.
constexpr SampleRate kVoiceFrameClock{kVoiceFramesPerSecond};

// The first voice frame shown at or after `t` seconds: synthesis's rule (first_frame_at,
// voice_frame_grid.hpp), so that a corpus frame belongs to the phone on screen at its instant as
// a target frame does; a unit and its target then start alike, and nothing trails by half a frame
// (spec/voice.md, "Corpus"). An edge within a microsecond of a frame's instant is on it: a
// TextGrid's decimal seconds are not exact.
std::int64_t first_frame_at_s(double t) {
  constexpr double kFrames = static_cast<double>(kVoiceFramesPerSecond);
  return static_cast<std::int64_t>(std::ceil(t * kFrames - 1e-6 * kFrames));
}

[[noreturn]] void refuse(const fs::path& file, const std::string& rule, const std::string& detail) {
  throw InputError({file.string(), std::nullopt, std::nullopt}, rule, detail);
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

template <std::size_t N>
bool has_extension(const fs::path& file, const std::string_view (&extensions)[N]) {
  const std::string e = lower(file.extension().string());
  return std::find(std::begin(extensions), std::end(extensions), e) != std::end(extensions);
}

std::string extension_list(const auto& extensions) {
  std::string out;
  for (std::string_view e : extensions) out += (out.empty() ? "" : ", ") + std::string(e);
  return out;
}

// A manifest frame_rate_hz: a positive finite number.
double manifest_rate(const nlohmann::json& value, const fs::path& manifest, const std::string& where) {
  if (!value.is_number() || !std::isfinite(value.get<double>()) || !(value.get<double>() > 0))
    refuse(manifest, "corpus-manifest", where + "\"frame_rate_hz\" must be a positive number");
  return value.get<double>();
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
  std::optional<double> session_rate;
  if (const auto it = j.find("frame_rate_hz"); it != j.end()) session_rate = manifest_rate(*it, manifest, "");
  if (const auto it = j.find("phone_set"); it != j.end()) {
    static const std::map<std::string, CorpusPhoneSet> kSets{{"auto", CorpusPhoneSet::arpabet_or_timit},
                                                             {"arpabet", CorpusPhoneSet::arpabet},
                                                             {"timit", CorpusPhoneSet::timit},
                                                             {"espeak", CorpusPhoneSet::espeak}};
    const auto set = it->is_string() ? kSets.find(it->get<std::string>()) : kSets.end();
    if (set == kSets.end()) refuse(manifest, "corpus-manifest", "\"phone_set\" must be \"auto\", \"arpabet\", \"timit\" or \"espeak\"");
    listing.phone_set = set->second;
  }
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
    if (!has_extension(entry.markers, kMarkerExtensions))
      refuse(manifest, "corpus-format", where + ".files.markers: \"" + entry.markers.filename().string() +
                                            "\" is not a marker file the build reads (" + extension_list(kMarkerExtensions) + ")");
    entry.alignment = corpus_file(directory, json_string(*files, "alignment", manifest, where + ".files"), manifest, where);
    if (!has_extension(entry.alignment, kAlignmentExtensions))
      refuse(manifest, "corpus-format", where + ".files.alignment: \"" + entry.alignment.filename().string() +
                                            "\" is not an alignment the build reads (.TextGrid, .lab)");
    entry.frame_rate_hz = session_rate;
    if (const auto rate = u.find("frame_rate_hz"); rate != u.end()) entry.frame_rate_hz = manifest_rate(*rate, manifest, where + ": ");
    listing.utterances.push_back(std::move(entry));
  }
  return listing;
}

// A label's phone in `set`; `closure` is set for a TIMIT stop closure. nullopt when unknown.
std::optional<Phone> phone_in_set(const std::string& label, CorpusPhoneSet set, bool& closure) {
  closure = false;
  const std::string l = lower(label);
  if (l.empty() || l == "sil" || l == "sp" || l == "pau") return Phone::SIL;
  const auto timit = [&]() -> std::optional<Phone> {
    try {
      const TimitPhone t = phone_from_timit(label, "");
      closure = t.closure;
      return t.phone;
    } catch (const std::invalid_argument&) {
      return std::nullopt;
    }
  };
  try {
    switch (set) {
      case CorpusPhoneSet::arpabet_or_timit:
        try {
          return parse_arpabet(label, "").phone;
        } catch (const std::invalid_argument&) {
          return timit();
        }
      case CorpusPhoneSet::arpabet: return parse_arpabet(label, "").phone;
      case CorpusPhoneSet::timit: return timit();
      case CorpusPhoneSet::espeak: return phone_from_espeak(label, "");
    }
  } catch (const std::invalid_argument&) {
  }
  return std::nullopt;
}

std::string_view phone_set_name(CorpusPhoneSet set) {
  switch (set) {
    case CorpusPhoneSet::arpabet_or_timit: return "an ARPAbet phone or a TIMIT label";
    case CorpusPhoneSet::arpabet: return "an ARPAbet phone";
    case CorpusPhoneSet::timit: return "a TIMIT label";
    case CorpusPhoneSet::espeak: return "an espeak-ng phoneme";
  }
  return "";
}

// A take's markers as read from its file, in mm at the file's rate.
struct CapturedMarkers {
  MarkerFrames<Millimetres> set;
  bool synthetic = false;
  std::string rate_field;  // what the file calls its rate, for messages
};

CapturedMarkers read_markers(const fs::path& file) {
  const std::string e = lower(file.extension().string());
  if (e == ".c3d") {
    C3dFile c3d = read_c3d(slurp(file), file.string());
    return {std::move(c3d.markers), c3d.text_parameters.count("FAPCAST:SYNTHETIC") > 0, "POINT:RATE"};
  }
  if (e == ".trc") return {read_trc(slurp(file), file.string()), false, "DataRate"};
  if (e == ".csv") return {read_marker_csv(slurp(file), file.string()), false, "the frame rate"};
  refuse(file, "corpus-format", "not a marker file the build reads (" + extension_list(kMarkerExtensions) + ")");
}

// A take's phone intervals as read from its alignment, with each one's line where the format has
// lines (.lab) for messages.
struct AlignedPhones {
  std::vector<Interval> intervals;
  std::vector<std::optional<std::uint64_t>> lines;
  double end_s = 0;
  bool synthetic = false;
};

AlignedPhones read_alignment(const fs::path& file) {
  AlignedPhones out;
  if (lower(file.extension().string()) == ".lab") {
    LabFile lab = read_lab(slurp(file), file.string());
    out.end_s = lab.segments.empty() ? 0 : lab.segments.back().end_s;
    out.lines.assign(lab.lines.begin(), lab.lines.end());
    out.intervals = std::move(lab.segments);
    return out;
  }
  const Alignment alignment = read_textgrid(slurp(file), file.string());
  const LabelTier* phones = alignment.find("phones");
  if (phones == nullptr || phones->kind != TierKind::intervals)
    refuse(file, "corpus-alignment", "no interval tier named \"phones\"");
  out.intervals = phones->intervals;
  out.lines.resize(out.intervals.size());
  out.end_s = alignment.end_s;
  out.synthetic = is_synthetic(alignment);
  return out;
}

// The phones forced alignment finds in `speech` from `transcript` (ARPAbet labels, silence
// empty): one aligner per thread, its model loaded once.
AlignedPhones align_take(const fs::path& speech, const fs::path& transcript) {
  thread_local SpeechAligner aligner;
  const Audio audio = read_wav(speech);
  const Transcript text = parse_transcript(decode_text(slurp(transcript), transcript.string(), "transcript"), transcript.string());
  const SpeechAlignment found = aligner.align(audio, text, speech.string());
  AlignedPhones out;
  const double rate = static_cast<double>(audio.sample_rate.hz);
  for (const TimedPhone& p : timed_phones(found))
    out.intervals.push_back({static_cast<double>(p.start_sample) / rate, static_cast<double>(p.end_sample) / rate,
                             p.phone == Phone::SIL ? std::string() : std::string(arpabet(p.phone))});
  out.lines.resize(out.intervals.size());
  out.end_s = static_cast<double>(found.samples) / rate;
  return out;
}

// Refuses a stem with more than one candidate file, naming them.
void refuse_ambiguous(const std::vector<fs::path>& files, const char* what) {
  std::string names;
  for (const fs::path& f : files) names += (names.empty() ? "" : " and ") + f.filename().string();
  const std::string count = files.size() == 2 ? "two" : std::to_string(files.size());
  refuse(files.front(), "corpus-ambiguous", count + " " + what + " for utterance \"" + files.front().stem().string() +
                                                "\": " + names + " (keep one, or list the pair in manifest.json)");
}

}  // namespace

CorpusListing list_corpus(const fs::path& directory) {
  if (!fs::is_directory(directory)) refuse(directory, "corpus-missing", "not a directory");
  CorpusListing listing;
  if (const fs::path manifest = directory / "manifest.json"; fs::exists(manifest)) {
    listing = read_manifest(directory, manifest);
  } else {
    listing.directory = directory;
    std::map<std::string, std::vector<fs::path>> markers, alignments;  // stem -> candidates
    for (const auto& entry : fs::directory_iterator(directory)) {
      if (!entry.is_regular_file()) continue;
      if (has_extension(entry.path(), kMarkerExtensions)) markers[entry.path().stem().string()].push_back(entry.path());
      if (has_extension(entry.path(), kAlignmentExtensions)) alignments[entry.path().stem().string()].push_back(entry.path());
    }
    for (auto& [stem, files] : markers) {
      std::sort(files.begin(), files.end());
      if (files.size() > 1) refuse_ambiguous(files, "marker files");
      const auto grid = alignments.find(stem);
      if (grid == alignments.end()) {
        fs::path speech = files.front(), transcript = files.front();
        speech.replace_extension(".wav");
        transcript.replace_extension(".txt");
        if (fs::is_regular_file(speech) && fs::is_regular_file(transcript)) {
          listing.utterances.push_back({stem, files.front(), {}, speech, transcript, std::nullopt});
          continue;
        }
        fs::path expected = files.front();
        expected.replace_extension(".TextGrid");
        refuse(expected, "corpus-file-missing", "no alignment (.TextGrid or .lab) beside " + files.front().filename().string());
      }
      std::sort(grid->second.begin(), grid->second.end());
      if (grid->second.size() > 1) refuse_ambiguous(grid->second, "alignments");
      listing.utterances.push_back({stem, files.front(), grid->second.front(), {}, {}, std::nullopt});
    }
  }
  if (listing.utterances.empty())
    refuse(directory, "corpus-empty", "no utterance (manifest.json lists none, or no marker file (" + extension_list(kMarkerExtensions) +
                                          ") with an alignment (.TextGrid, .lab) of the same stem)");
  return listing;
}

CorpusTake read_corpus_take(const CorpusListing& listing, std::size_t index) {
  const CorpusUtterance& u = listing.utterances.at(index);
  CorpusTake take;
  take.id = u.id;
  CapturedMarkers captured = read_markers(u.markers);
  const double rate = captured.set.frame_rate_hz;
  take.capture_frame_rate_hz = rate;
  // C3D keeps its rate as a float32: agree to float precision.
  if (u.frame_rate_hz && std::abs(rate - *u.frame_rate_hz) > 1e-6 * *u.frame_rate_hz)
    refuse(u.markers, "corpus-frame-rate", captured.rate_field + " is " + shortest_decimal(rate) + " Hz, manifest.json says " +
                                               shortest_decimal(*u.frame_rate_hz));
  if (!(rate >= kMinCaptureFramesPerSecond))
    refuse(u.markers, "corpus-frame-rate", captured.rate_field + " is " + shortest_decimal(rate) + " Hz; the voice build resamples takes of " +
                                               shortest_decimal(kMinCaptureFramesPerSecond) + " Hz or more to 60, not slower ones");
  // A rate within float precision of 60 (C3D's float32, a CSV rate derived from its times) is 60.
  const bool on_grid = std::abs(rate - kVoiceFramesPerSecond) <= 1e-6 * kVoiceFramesPerSecond;
  const MarkerFrames<Millimetres> set = on_grid ? std::move(captured.set) : resample_markers(captured.set, kVoiceFramesPerSecond);
  const auto sites = marker_sites();
  const Eigen::Index frames = set.frame_count();
  MarkerFrames<Centimetres>& m = take.markers;
  m.frame_rate_hz = kVoiceFramesPerSecond;
  m.positions = Eigen::MatrixXd::Constant(3 * static_cast<Eigen::Index>(sites.size()), frames, std::nan(""));
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
      if (set.present(k, f)) m.positions.block<3, 1>(3 * r, f) = set.at(k, f) / 10.0;
  }
  for (std::size_t r = 0; r < sites.size(); ++r)
    if (!found[r]) refuse(u.markers, "corpus-markers", "no marker for site " + std::string(sites[r].label) +
                                                           " (label it so, or map a label to it in manifest.json's marker_map)");

  const bool from_speech = u.alignment.empty();
  const fs::path& timing = from_speech ? u.speech : u.alignment;  // what messages about the phones name
  const AlignedPhones aligned_phones = from_speech ? align_take(u.speech, u.transcript) : read_alignment(u.alignment);
  const std::int64_t aligned = alignment_sample(aligned_phones.end_s, kVoiceFrameClock, timing.string(), "its end");
  if (std::llabs(aligned - frames) > kMaxLengthMismatchFrames)
    refuse(timing, "corpus-length", "the alignment ends at frame " + std::to_string(aligned) + " (" +
                                             std::to_string(aligned_phones.end_s) + " s), " + u.markers.filename().string() +
                                             " has " + std::to_string(frames) + " frames at 60 fps");
  bool previous_closure = false;
  for (std::size_t i = 0; i < aligned_phones.intervals.size(); ++i) {
    const Interval& iv = aligned_phones.intervals[i];
    bool closure = false;
    const std::optional<Phone> phone = phone_in_set(iv.label, listing.phone_set, closure);
    if (!phone) {
      const std::string what = "\"" + iv.label + "\" is not " + std::string(phone_set_name(listing.phone_set));
      if (const auto line = aligned_phones.lines[i])
        throw InputError({timing.string(), *line, std::nullopt}, "corpus-alignment", what);
      refuse(timing, "corpus-alignment", "phones interval " + std::to_string(i + 1) + ": " + what);
    }
    const Phone p = *phone;
    const auto clamp = [&](double t) { return std::clamp<std::int64_t>(first_frame_at_s(t), 0, frames); };
    const std::int64_t first = clamp(iv.start_s);
    const std::int64_t end = clamp(iv.end_s);
    if (end <= first) continue;
    const bool adjacent = !take.phones.empty() && take.spans.back().first + take.spans.back().count == first;
    // Adjacent silences merge, and so do a stop's closure and its release.
    if (adjacent && p == take.phones.back() && (p == Phone::SIL || previous_closure)) {
      take.spans.back().count += static_cast<std::uint32_t>(end - first);
      previous_closure = closure;
      continue;
    }
    take.phones.push_back(p);
    take.spans.push_back({static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(end - first)});
    previous_closure = closure;
  }
  take.synthetic = captured.synthetic || aligned_phones.synthetic;
  if (take.phones.empty()) refuse(timing, "corpus-alignment", "the phones tier has no interval of a frame or more");
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

Eigen::MatrixXd source_vectors_m(const MarkerFrames<Centimetres>& stabilised, const std::string& source) {
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

}  // namespace fapcast
