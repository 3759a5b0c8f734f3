#pragma once
// Reading a capture corpus for the voice build (spec/corpus.md layout, spec/voice.md "Corpus"):
// the utterance list (manifest.json, or *.c3d paired with *.TextGrid by stem), one take at a time
// as markers in marker_sites() order plus its phone segments on the 60 fps frame grid, and the
// source marker vectors the RBF map reads (feature points only, metres, head frame).
#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "fapcast/synth/marker_frames.hpp"
#include "fapcast/synth/phone.hpp"
#include "fapcast/synth/phone_graph.hpp"

namespace fapcast::synth {

// The voice build's frame rate: the paper's capture rate and the reference talker's.
inline constexpr int kVoiceFramesPerSecond = 60;
// Largest disagreement between a take's marker frames and its alignment's end, in frames.
inline constexpr std::int64_t kMaxLengthMismatchFrames = 3;

struct CorpusUtterance {
  std::string id;
  std::filesystem::path markers;    // C3D
  std::filesystem::path alignment;  // TextGrid
};

struct CorpusListing {
  std::filesystem::path directory;
  bool synthetic = false;            // the manifest says so
  std::string label;                 // the manifest's "provenance" text, if any
  std::optional<std::uint64_t> seed; // the manifest's "seed" (reference corpora), if any
  std::map<std::string, std::string> marker_map;  // file label -> FP label, "rigid" or "ignore"
  std::vector<CorpusUtterance> utterances;
};

// Lists the corpus in `directory`: its manifest.json when present, else every *.c3d with a
// *.TextGrid of the same stem (sorted by name). Throws InputError: corpus-missing (no such
// directory), corpus-manifest (bad JSON or field, naming it), corpus-empty (no utterance),
// corpus-file-missing (a listed or paired file does not exist).
CorpusListing list_corpus(const std::filesystem::path& directory);

// One take as the build needs it.
struct CorpusTake {
  std::string id;
  MarkerFrames markers;              // marker_sites() order, cm, capture frame, NaN = missing
  std::vector<Phone> phones;         // phone segments in time order (adjacent silences merged)
  std::vector<FrameSpan> spans;      // their frames, relative to the take, each non-empty
  bool synthetic = false;            // the C3D (FAPCAST:SYNTHETIC) or the TextGrid says so
};

// Reads utterance `index`: the C3D (60 fps; markers mapped through the listing's marker_map to
// marker_sites() labels) and the TextGrid's "phones" tier (ARPAbet; "", sil, sp, pau = silence),
// each interval on frames [round(start x 60), round(end x 60)), empty ones dropped. Throws
// InputError: the readers' own rules, corpus-frame-rate, corpus-markers (a site has no marker),
// corpus-alignment (no phones tier, unknown phone), corpus-length (alignment and markers differ
// by more than kMaxLengthMismatchFrames).
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
Eigen::MatrixXd source_vectors_m(const MarkerFrames& stabilised, const std::string& source);

}  // namespace fapcast::synth
