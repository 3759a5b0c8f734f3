#pragma once
// The retargeting's lip-contact term (spec/voice.md, "Lip contact"). The RBF map (paper section
// 3.5) blends the target prototypes by how near a source frame is to each source prototype. A
// closure made with rounded or spread lips - the /m/ of "home", the /p/ of "keep" - is near the
// rounded (or spread) vowels in every coordinate but the lip gap, so the blend opens the target's
// mouth although the talker's lips touch: on the reference voice a quarter of the /p b m/ never
// came within 2 mm. Where the source's inner lips are near contact, the term adds as much of the
// target face's lip-closing shape as keeps the target's inner lips no further apart, above their
// own contact, than the source's are above theirs.
#include <Eigen/Core>

#include <optional>

#include "fapcast/math/rbf_retarget.hpp"

namespace fapcast {

struct LipContact {
  // What one unit of the closing shape moves on the target (D = 3N, metres, xyz interleaved).
  Eigen::VectorXd shape;
  // The generic target's inner-lip gap (2.2's y above 2.3's) as the map puts it, from the map's m
  // responses: gap_offset_m + gap_weights . phi. Kept apart from the map's weights so that a voice
  // adapted to another face (voice_adaptation.hpp) adds the same amounts as the generic one.
  Eigen::VectorXd gap_weights;
  double gap_offset_m = 0;
  double shape_gap_m = 0;        // the generic target's gap change per unit of shape (< 0)
  double source_contact_m = 0;   // source distance 2.2 - 2.3 with the lips together
  double target_contact_m = 0;   // generic target gap with the lips together
  double reach_m = 0;            // source lips further apart than contact + reach: no term
  Eigen::Index source_upper = 0, source_lower = 0;  // first source-vector row of 2.2 and 2.3

  // Most of the shape ever added: a closure in a frame the map leaves wide open is corrected no
  // further than 1.5 units of the shape (ICT's mouthClose closes an open jaw's lips at 1).
  static constexpr double kMaxAmount = 1.5;

  // How much of the shape a source frame x with map responses phi gets: 0 unless the source's
  // lips are within reach_m of contact and the target's are further above their contact than the
  // source's are above theirs; then enough to close that excess, faded out over the second half
  // of the reach (so it never jumps), at most kMaxAmount.
  double amount(const Eigen::Ref<const Eigen::VectorXd>& x, const Eigen::Ref<const Eigen::VectorXd>& phi) const;
  // The source's inner-lip distance (metres).
  double source_gap_m(const Eigen::Ref<const Eigen::VectorXd>& x) const;
};

// The voice's retargeting: the RBF map, then the lip-contact term when the voice has one. As an
// affine image of m (+ 1) responses, target = offset + weights^T responses, with the contact
// amount the last response and the closing shape the last weight row: the PCA of the build and
// every evaluation use it as they used the map alone.
class Retargeting {
 public:
  explicit Retargeting(const RbfMap& map, std::optional<LipContact> contact = std::nullopt);

  const RbfMap& map() const { return *map_; }
  const std::optional<LipContact>& contact() const { return contact_; }
  Eigen::Index response_count() const { return weights_.rows(); }  // m, or m + 1 with the term
  Eigen::Index source_dimension() const { return map_->source_dimension(); }
  Eigen::Index target_dimension() const { return map_->target_dimension(); }
  const Eigen::MatrixXd& weights() const { return weights_; }  // response_count() x D
  const Eigen::VectorXd& offset() const { return map_->offset(); }

  Eigen::VectorXd responses(const Eigen::Ref<const Eigen::VectorXd>& x) const;
  Eigen::VectorXd operator()(const Eigen::Ref<const Eigen::VectorXd>& x) const;
  // A chunk of source frames (d x c) into `out` (D x c, float32): the streaming PCA's path.
  void map_columns(const Eigen::Ref<const Eigen::MatrixXd>& sources, Eigen::Ref<Eigen::MatrixXf> out) const;

 private:
  const RbfMap* map_;
  std::optional<LipContact> contact_;
  Eigen::MatrixXd weights_;
};

}  // namespace fapcast
