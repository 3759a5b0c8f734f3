#pragma once
// A loaded, verified voice (spec/voice.md): everything the unit search
// and the concatenation need, in place in the memory-mapped file. Voice::open refuses any bad file
// with an InputError before the first frame is synthesised.
#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fapcast/core/input_error.hpp"
#include "fapcast/phonetics/phone.hpp"
#include "fapcast/select/phone_graph.hpp"
#include "fapcast/math/rbf_retarget.hpp"
#include "fapcast/voice/lip_contact.hpp"
#include "fapcast/voice/voice_file.hpp"

namespace fapcast {

// One MPEG-4 feature point on the voice's target face.
struct VoiceFeaturePoint {
  std::string label;          // "2.1", "8.3", ... (every FP of spec/markers.tsv except rigid H.*)
  std::int32_t vertex;        // target-mesh vertex index (0-based)
  Eigen::Vector3d neutral_m;  // position on the target face's NEUTRAL mesh, metres,
                              // axes: x = face's own left, y up, z forward (MPEG-4 and ICT agree)
};

// A rigid head marker: where it sits on the target face, and where the build's head frame put it
// on the source side (the reference every corpus take is stabilised against).
struct VoiceRigidMarker {
  std::string label;                   // "H.temple_l", ...
  std::int32_t vertex;                 // target-mesh vertex index
  Eigen::Vector3d neutral_m;           // on the target's neutral mesh, metres
  Eigen::Vector3d source_reference_m;  // source head frame, metres
};

class Voice {  // move-only
 public:
  // Maps and verifies `path`: the container (voice_file.hpp), the voice's sections and shapes,
  // the provenance, the feature points (FPNT) and the phone graph (GRPH). InputError on any bad
  // file; std::runtime_error when it cannot be opened.
  static Voice open(const std::filesystem::path& path);
  // The same checks on bytes the caller keeps alive for the voice's lifetime (8-byte aligned, as
  // VoiceFileView::over_bytes wants); `source` names them in errors. For tests and fuzzing.
  static Voice over_bytes(std::span<const std::byte> bytes, std::string source);

  Voice(Voice&&) noexcept;
  Voice& operator=(Voice&&) noexcept;
  Voice(const Voice&) = delete;
  Voice& operator=(const Voice&) = delete;
  ~Voice();

  const VoiceProvenance& provenance() const { return provenance_; }
  static constexpr int kFramesPerSecond = 60;  // corpus / PCA frame rate
  int component_count() const { return static_cast<int>(components_rows_); }  // k (17)
  Eigen::Index dimension() const { return dimension_; }                        // D = 3N
  Eigen::Map<const RowMajorMatrixXf> pca_mean() const;        // 1 x D, metres, xyz interleaved
  Eigen::Map<const RowMajorMatrixXf> pca_components() const;  // k x D
  Eigen::Map<const RowMajorMatrixXf> pca_variances() const;   // 1 x k, m^2
  Eigen::Map<const RowMajorMatrixXf> frame_coefficients() const;  // F x k, in place in the file
  const PhoneGraph& graph() const { return graph_; }          // states index frame_coefficients rows
  std::span<const Phone> state_phones() const { return phones_; }  // ARPAbet phone per state
  // Frame span of each corpus utterance in frame_coefficients (graph states' utterance indices).
  std::span<const FrameSpan> utterance_frames() const { return utterances_; }
  std::span<const VoiceFeaturePoint> feature_points() const { return feature_points_; }
  std::span<const VoiceRigidMarker> rigid_markers() const { return rigid_markers_; }
  // Source markers -> target mesh through the voice's RBF map (for evaluation). The source
  // vector is the feature points' markers in feature_points() order, metres, in the head frame
  // the rigid markers' source_reference_m define. Its double-precision matrices are made from
  // the file's sections on the first call (thread-safe): `say` never needs them.
  const RbfMap& retarget_map() const;
  // The whole retargeting: the map, then the lip-contact term when the voice has one (LCSH and
  // LCON; voices built before it have none). Made with the map, on the first call.
  const Retargeting& retargeting() const;
  // The per-vertex maps from the generic ICT face to this voice's face (N x 9, vertex i's 3 x 3
  // map row-major: displacement on this face = map * displacement on ICT) when the voice was
  // re-targeted (`fapcast voice retarget`, section FMAP); nullopt for a voice on ICT itself.
  std::optional<Eigen::Map<const RowMajorMatrixXf>> face_maps() const;
  // The container, for section sizes (voice info).
  const VoiceFileView& file() const { return view_; }

 private:
  // The voice-level checks (FPNT, GRPH, RPAR, FMAP ...) on a verified container.
  static Voice from_view(VoiceFileView view);
  Voice(VoiceFileView view, VoiceProvenance provenance, std::vector<VoiceFeaturePoint> feature_points,
        std::vector<VoiceRigidMarker> rigid_markers, PhoneGraph graph,
        std::vector<Phone> phones, std::vector<FrameSpan> utterances, double rbf_r_squared, double rbf_lambda);

  VoiceFileView view_;
  VoiceProvenance provenance_;
  Eigen::Index components_rows_ = 0;
  Eigen::Index dimension_ = 0;
  std::vector<VoiceFeaturePoint> feature_points_;
  std::vector<VoiceRigidMarker> rigid_markers_;
  PhoneGraph graph_;
  std::vector<Phone> phones_;
  std::vector<FrameSpan> utterances_;
  double rbf_r_squared_ = 0.0;  // RPAR, checked at open
  double rbf_lambda_ = 0.0;
  struct RetargetMapOnce;  // the map, made once on demand
  std::unique_ptr<RetargetMapOnce> map_;
};

// The FPNT section's JSON for these points (spec/voice.md, "Feature points").
std::string voice_feature_points_json(std::span<const VoiceFeaturePoint> feature_points,
                                      std::span<const VoiceRigidMarker> rigid_markers);

}  // namespace fapcast
