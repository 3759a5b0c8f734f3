#pragma once
// Held-out evaluation of synthesis (Ma et al. 2006, section 4; `fapcast eval synth`): the
// reference talker records sentences no voice has seen (SYNTHETIC), every system synthesises each
// from the sentence's own phone timing, and the result is scored on the target face against the
// recording mapped through the voice's retargeting map (synthesis_score.hpp).
#include "fapcast/eval/diviseme_baseline.hpp"
#include "fapcast/eval/dominance_baseline.hpp"
#include "fapcast/face/face_model.hpp"
#include "fapcast/corpus/marker_frames.hpp"
#include "fapcast/eval/synthesis_score.hpp"
#include "fapcast/frontend/text_frontend.hpp"
#include "fapcast/synthesis/unit_concatenation.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace fapcast {

// One held-out utterance: what the reference talker recorded and the timing systems follow.
struct HeldOutUtterance {
  std::string id;                    // "heldout01", ...
  std::string text;
  Speech speech;                     // audio and timed phones
  std::vector<TargetPhone> targets;  // the phones on the 60 fps grid (place_on_voice_grid)
  MarkerFrames<Centimetres> recorded;             // ground truth: the actor's clean markers (cm, 60 fps)
};

// Records the first `count` of kHeldOutSentences (at most all of them) on `actor`, drawing each
// take's variation from `seed` (one split stream per take, as the corpus recorder does).
std::vector<HeldOutUtterance> record_held_out(const FaceModel& actor, std::uint64_t seed,
                                              std::size_t count);

// What a system made of one utterance: PCA coefficient frames (frames x k) from the utterance's
// first target frame on, and how many units it concatenated (0: not a concatenative system).
struct SystemOutput {
  Eigen::MatrixXf coefficients;
  std::size_t units = 0;
};

struct NamedSystem {
  std::string name;
  std::function<SystemOutput(const HeldOutUtterance&)> synthesise;
};

// The two baselines over a voice's phone graph and PCA frames (frames x k); both keep a
// reference to the graph, the diviseme system its view of the frames (both must outlive it, as
// a Voice's do). A target class the voice never recorded is replaced as synthesize() replaces it
// (covered_viseme), so every system says the same visemes.
NamedSystem diviseme_system(const PhoneGraph& graph, Eigen::Map<const RowMajorMatrixXf> pca_frames,
                            ConcatenationOptions options = {},
                            DivisemeChoiceRule rule = DivisemeChoiceRule::kBestDuration);
NamedSystem dominance_system(const PhoneGraph& graph, const PcaFrames& pca_frames,
                             DominanceBaselineOptions options = {});

// The target face as the evaluation sees it.
struct EvaluationFace {
  Eigen::Map<const RowMajorMatrixXf> pca_mean{nullptr, 0, 0};        // 1 x D, metres
  Eigen::Map<const RowMajorMatrixXf> pca_components{nullptr, 0, 0};  // k x D
  const Retargeting* retarget_map = nullptr;            // source markers -> target mesh
  // The map's source vectors of a take (d x frames), built exactly as the voice build built the
  // vectors it fitted the map on.
  std::function<Eigen::MatrixXd(const MarkerFrames<Centimetres>&)> source_vectors;
  EvaluationPoints points;
};

class Voice;

// The evaluation's view of a voice: its PCA basis and RBF map, its feature points and temple
// markers, and source vectors built as the voice build built them (head-stabilised against the
// voice's rigid reference, feature points only, metres: voice_corpus.hpp). Keeps references
// into `voice`. Throws std::runtime_error naming the voice file when it lacks a rigid marker.
EvaluationFace evaluation_face(const Voice& voice);

// The reference actor whose corpus `voice` was built from: reference_actor(the ICT face, the
// corpus's seed), the seed read from the provenance parameter `corpus_seed` that the voice build
// copies from a reference corpus's manifest. (The provenance's own `seed` is the build's EM-PCA
// start, not the corpus's.) Held-out takes must be recorded by this actor: another actor's face
// is another retargeting problem, and the scores would be meaningless. Throws
// std::runtime_error naming the voice file for a voice not built from a reference corpus (not
// synthetic, or no whole `corpus_seed`).
FaceModel held_out_actor(const Voice& voice);

struct SystemReport {
  std::string name;
  SynthesisScore score;
  double units_per_phone = 0;  // units / target phones; 0 for a non-concatenative system
};

// Lip curves (mm on the target face) of one utterance, for plots.
struct UtteranceCurves {
  std::string id;
  std::string text;
  LipCurves recorded;
  std::vector<LipCurves> synthesised;  // one per system, in system order
};

struct EvaluationReport {
  std::vector<SystemReport> systems;
  std::vector<UtteranceCurves> utterances;
  std::size_t phones = 0;  // target phones over all utterances
  std::size_t frames = 0;  // recorded frames over all utterances
};

// The delay that best aligns system `system`'s lip height with the recorded one in each
// utterance (trajectory_agreement at 60 fps over -100..+100 ms in 1 ms steps; + = the system
// behind), and the median over utterances: a check of the whole pipeline's timing on its own
// talker (spec/evaluation.md). nullopt when no utterance has 3 frames.
std::optional<double> median_lip_height_lag_ms(const EvaluationReport& report, std::size_t system);

// Scores every system on every utterance. Throws std::invalid_argument when the face is
// incomplete or a system's coefficients do not have the face's k columns.
EvaluationReport evaluate_synthesis(const EvaluationFace& face, std::span<const NamedSystem> systems,
                                    std::span<const HeldOutUtterance> utterances);

}  // namespace fapcast
