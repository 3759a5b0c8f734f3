#pragma once
// The voice build (Ma et al. 2006, sections 3.3-3.7; spec/voice.md "Building"): corpus ->
// preprocessed takes -> source prototypes and target prototypes -> RBF map (r^2 over all frames,
// lambda by GCV) -> PCA of the retargeted corpus (exact route, or EM-PCA) -> every frame's
// coefficients -> phone graph -> one voice file. Deterministic: the same corpus and options give
// the same bytes.
#include "fapcast/core/input_error.hpp"
#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

namespace fapcast {

enum class PcaRoute {
  exact,  // pca_of_affine_image: the retargeted frames lie in an m-dimensional affine space
  em,     // em_pca: streaming EM-PCA over the retargeted frames (Roweis 1998)
};

// The target face every voice is built onto today.
inline constexpr std::string_view kDefaultTargetFace = "ICT-FaceKit generic neutral (data/ict-facekit)";

struct VoiceBuildOptions {
  PcaRoute pca = PcaRoute::exact;
  int components = 17;           // k
  std::uint64_t seed = 1;        // EM-PCA's random start (recorded either way)
  // EM-PCA's stopping rule (EmPcaOptions): at most this many passes after the mean pass, fewer
  // when the subspace moves less than the tolerance (sine of the largest principal angle).
  int em_max_iterations = 300;
  double em_tolerance = 1e-5;
  std::string corpus_name;       // provenance "corpus"; empty = the directory as given
  std::string build_time_utc;    // provenance, as given (the CLI uses SOURCE_DATE_EPOCH or now)
  std::string tool_version;
  // Progress: stage ("read", "fit", "pca", "coefficients", "write"), done, total. May be empty.
  std::function<void(std::string_view stage, std::size_t done, std::size_t total)> progress;
};

struct VoiceBuildSummary {
  std::size_t utterances = 0;
  std::size_t states = 0;
  std::int64_t frames = 0;
  std::size_t prototypes = 0;   // m: viseme classes present in the corpus
  Eigen::Index target_rank = 0; // centred rank of the target prototypes
  double r_squared_m2 = 0;
  double lambda = 0;
  double gcv = 0;
  bool lambda_at_range_edge = false;
  double explained_fraction = 0;  // of the retargeted corpus's variance, by the k components
  int pca_iterations = 0;
  bool pca_converged = true;
  std::size_t pattern_filled_gaps = 0;  // long marker gaps filled from a donor (pattern_fill.hpp)
  bool lip_contact = false;        // the retargeting has the lip-contact term (a bilabial class)
  double source_contact_m = 0;     // its source and target contact gaps
  double target_contact_m = 0;
  std::int64_t lip_contact_frames = 0;  // corpus frames it moved
  double seconds_read = 0, seconds_fit = 0, seconds_pca = 0, seconds_total = 0;
};

struct BuiltVoice {
  std::string bytes;  // the voice file (write it with write_file_atomically)
  VoiceBuildSummary summary;
};

// Builds the voice of the corpus in `corpus_dir` onto the generic ICT face. Throws InputError for
// a bad corpus (voice_corpus.hpp rules, and voice-prototypes when the corpus covers too few viseme
// classes for k components) and std::invalid_argument for bad options.
BuiltVoice build_voice(const std::filesystem::path& corpus_dir, const VoiceBuildOptions& options);

// "exact" / "em".
std::string_view pca_route_name(PcaRoute route);

}  // namespace fapcast
