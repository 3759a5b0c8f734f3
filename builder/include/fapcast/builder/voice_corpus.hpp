#pragma once
// Reading a capture corpus for the voice build (spec/corpus.md layout, spec/voice.md "Corpus"):
// the utterance list (manifest.json, or marker files paired with alignments by stem), one take
// at a time as markers in marker_sites() order plus its phone segments on the 60 fps frame grid,
// and the source marker vectors the RBF map reads (feature points only, metres, head frame).
// Markers: C3D, TRC or marker CSV (any rate >= kMinCaptureFramesPerSecond, resampled to 60 fps);
// alignments: Praat TextGrid ("phones" tier) or HTK/MOCHA .lab.
#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fapcast/core/input_error.hpp"
#include "fapcast/corpus/marker_frames.hpp"
#include "fapcast/phonetics/phone.hpp"
#include "fapcast/select/phone_graph.hpp"
#include "fapcast/voice/voice_frame_grid.hpp"

namespace fapcast {

// Slowest capture the build resamples to 60 fps; slower takes are refused (corpus-frame-rate).
inline constexpr double kMinCaptureFramesPerSecond = 50;
// Largest disagreement between a take's marker frames and its alignment's end, in frames.
inline constexpr std::int64_t kMaxLengthMismatchFrames = 3;

// The symbols a corpus's phone labels are spelt in (manifest.json "phone_set"; phone_map.hpp).
enum class CorpusPhoneSet {
  arpabet_or_timit,  // "auto" (the default): ARPAbet (stress digits allowed), else a TIMIT label
  arpabet,           // "arpabet": CMUdict ARPAbet only
  timit,             // "timit": the 61 TIMIT / MOCHA-TIMIT labels only
  espeak,            // "espeak": espeak-ng en-us mnemonics
};
// In every set, "", sil, sp and pau are silence.

struct CorpusUtterance {
  std::string id;
  std::filesystem::path markers;    // .c3d, .trc or .csv (marker CSV)
  std::filesystem::path alignment;  // .TextGrid or .lab; empty when the take is aligned from:
  std::filesystem::path speech;     //   its recording (.wav) and
  std::filesystem::path transcript; //   what it says (.txt), by forced alignment (spec/recognise.md)
  // The manifest's frame_rate_hz for it (utterance, else session), which the marker file's rate
  // must agree with; nullopt when not stated.
  std::optional<double> frame_rate_hz;
};

struct CorpusListing {
  std::filesystem::path directory;
  bool synthetic = false;            // the manifest says so
  std::string label;                 // the manifest's "provenance" text, if any
  std::optional<std::uint64_t> seed; // the manifest's "seed" (reference corpora), if any
  std::map<std::string, std::string> marker_map;  // file label -> FP label, "rigid" or "ignore"
  CorpusPhoneSet phone_set = CorpusPhoneSet::arpabet_or_timit;  // the manifest's "phone_set"
  std::vector<CorpusUtterance> utterances;
};

// The marker and alignment file extensions the build reads (compared case-insensitively).
inline constexpr std::string_view kMarkerExtensions[] = {".c3d", ".trc", ".csv"};
inline constexpr std::string_view kAlignmentExtensions[] = {".textgrid", ".lab"};

// Lists the corpus in `directory`: its manifest.json when present, else, sorted by stem, every
// marker file (kMarkerExtensions) with the one alignment (kAlignmentExtensions) of the same stem,
// or, when it has none, with the .wav and .txt of the same stem (the take's speech and transcript).
// There is no precedence between formats: two marker files or two alignments of one stem are
// refused. Throws InputError: corpus-missing (no such directory), corpus-manifest (bad JSON or
// field, naming it), corpus-empty (no utterance), corpus-file-missing (a listed or paired file
// does not exist), corpus-ambiguous (one stem, two marker files or two alignments, naming both),
// corpus-format (a manifest file of an extension the build does not read).
CorpusListing list_corpus(const std::filesystem::path& directory);

// One take as the build needs it.
struct CorpusTake {
  std::string id;
  MarkerFrames<Centimetres> markers;              // marker_sites() order, cm, capture frame, NaN = missing
  std::vector<Phone> phones;         // phone segments in time order (adjacent silences merged)
  std::vector<FrameSpan> spans;      // their frames, relative to the take, each non-empty
  bool synthetic = false;            // the C3D (FAPCAST:SYNTHETIC) or the TextGrid says so
  double capture_frame_rate_hz = kVoiceFramesPerSecond;  // the marker file's rate (resampled from)
};

// Reads utterance `index`: the marker file (resampled to 60 fps by resample_markers when its
// rate differs; markers mapped through the listing's marker_map to marker_sites() labels) and
// the alignment (the TextGrid's "phones" tier, or the .lab's segments, or the phones SpeechAligner
// finds in the take's speech from its transcript: noises and unmatched speech as silence) in the
// listing's phone set, each interval on frames [round(start x 60), round(end x 60)), empty ones dropped; a TIMIT
// stop closure (bcl ... kcl) is merged with the release of the same stop right after it. Throws
// InputError: the readers' own rules, corpus-frame-rate (below kMinCaptureFramesPerSecond, or
// not the manifest's frame_rate_hz), corpus-markers (a site has no marker), corpus-alignment (no
// phones tier, an unknown label: file:line for .lab), corpus-length (alignment and markers
// differ by more than kMaxLengthMismatchFrames).
CorpusTake read_corpus_take(const CorpusListing& listing, std::size_t index);

// Rows (in marker_sites()) of the feature points the source vector holds: every non-rigid site.
std::vector<std::size_t> source_marker_rows();

// The rigid markers' positions (3 x 5, cm) at the first frame of `take` where all are present:
// the head frame every take of the corpus is brought into. Throws InputError corpus-markers when
// no frame has them all.
Eigen::Matrix3Xd corpus_rigid_reference(const CorpusTake& take, const std::string& source);

// The source vectors of a head-stabilised take: d x F, d = 3 x source_marker_rows().size(),
// metres. Samples still missing after gap filling are interpolated linearly in time (held at the
// take's ends), so every frame maps; throws InputError corpus-markers when a feature point is
// missing throughout the take.
Eigen::MatrixXd source_vectors_m(const MarkerFrames<Centimetres>& stabilised, const std::string& source);

}  // namespace fapcast
