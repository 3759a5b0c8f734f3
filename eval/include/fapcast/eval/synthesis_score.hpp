#pragma once
// Scoring synthesised visual speech against a recording (Ma et al. 2006, section 4.1), on the
// target face: lip height, width and protrusion curves (lip_measures.hpp: normalised error and
// correlation), the jaw's opening at the chin, and feature-point trajectories (RMS distance in mm
// over the lip feature points and over all of them). Used by `fapcast eval synth` for the
// variable-length search and its baselines alike.
#include "fapcast/eval/lip_measures.hpp"
#include "fapcast/voice/lip_contact.hpp"
#include "fapcast/voice/voice_file.hpp"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace fapcast {

// The target-mesh vertices the score looks at: the face's feature points, then the two rigid
// temple points that anchor lip protrusion (lip_measures.hpp).
struct EvaluationPoints {
  std::vector<std::string> labels;            // "2.2", ..., "H.temple_l", "H.temple_r"
  std::vector<std::int32_t> vertices;         // target-mesh vertex of each label
  std::vector<std::size_t> feature_points;    // indices into `vertices`: every feature point
  std::vector<std::size_t> lip_points;        // indices of the lip feature points (2.x inner, 8.x outer)
  std::array<std::int32_t, 6> lip_measure{};  // indices of kLipMarkerLabels, for lip_curves()
  std::optional<std::size_t> chin;            // index of FP 2.1 (bottom of the chin), when the face has it
};

// The temple vertices of the ICT-FaceKit topology (H.temple_l, H.temple_r of marker_sites()),
// for target faces built on it.
std::array<std::int32_t, 2> ict_temple_vertices();

// Builds the points from the face's feature points (parallel label / vertex lists) and its
// temple vertices. Throws std::invalid_argument when a label repeats, the lists differ in length,
// or a lip-measure feature point (8.1-8.4) is missing.
EvaluationPoints evaluation_points(std::span<const std::string> labels,
                                   std::span<const std::int32_t> vertices,
                                   std::array<std::int32_t, 2> temple_vertices = ict_temple_vertices());

// Vertex positions for PCA frames: row n holds the xyz of each of `vertices` (frames x 3V) for
// the mesh mean + coefficients.row(n) * components. mean is 1 x D, components k x D (rows are
// components, xyz interleaved per vertex, as in the voice), coefficients frames x k.
Eigen::MatrixXf vertex_tracks(const Eigen::Ref<const RowMajorMatrixXf>& mean,
                              const Eigen::Ref<const RowMajorMatrixXf>& components,
                              const Eigen::MatrixXf& coefficients,
                              std::span<const std::int32_t> vertices);

// Vertex positions of source frames through a voice's retargeting (the RBF map and its lip-contact
// term): `sources` is d x F (one source marker vector per column, as the map was fitted on), the
// result F x 3V. Only the columns of `vertices` are evaluated (3V of the map's D outputs).
Eigen::MatrixXf vertex_tracks(const Retargeting& map, const Eigen::MatrixXd& sources,
                              std::span<const std::int32_t> vertices);

struct SynthesisScore {
  LipAgreement lips;         // normalised error % and correlation, all utterances as one curve
  // The jaw's opening: how far the chin (FP 2.1) sits below the temple reference, along the
  // face's up axis (+y), in metres like the lip curves; frames 0 when the face has no FP 2.1.
  CurveAgreement jaw;
  double lip_rms_mm = 0;     // RMS distance over the lip feature points and frames
  double all_rms_mm = 0;     // RMS distance over every feature point and frame
  std::size_t frames = 0;    // frames compared
  std::size_t utterances = 0;
};

// Accumulates one system's utterances. Tracks are frames x 3V over EvaluationPoints::vertices,
// in metres; an utterance is compared over the frames both tracks have (a synthesised track
// ends with its last target phone, a recording with its audio; they differ by a frame or two).
class SynthesisScorer {
 public:
  explicit SynthesisScorer(EvaluationPoints points);
  void add(const Eigen::MatrixXf& recorded, const Eigen::MatrixXf& synthesised);
  SynthesisScore score() const;
  const EvaluationPoints& points() const { return points_; }

 private:
  EvaluationPoints points_;
  LipCurves recorded_, synthesised_;
  std::vector<double> recorded_jaw_, synthesised_jaw_;
  double lip_sum_squared_m2_ = 0, all_sum_squared_m2_ = 0;
  std::size_t frames_ = 0, utterances_ = 0;
};

}  // namespace fapcast
