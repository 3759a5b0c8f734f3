#include "fapcast/synthesis/jaw_level.hpp"

#include "fapcast/math/zero_phase_lowpass.hpp"

#include <stdexcept>
#include <string>

namespace fapcast {

void level_jaw(const JawGuide& guide, const TargetTimeline& timeline, Eigen::MatrixXf& pca_frames, double cutoff_hz,
               double strength) {
  if (!(strength >= 0.0 && strength <= 1.0))
    throw std::invalid_argument("level_jaw: strength " + std::to_string(strength) + " is outside [0, 1]");
  if (strength == 0.0 || guide.jaw_move.empty() || timeline.phones.empty()) return;
  const Eigen::Index k = static_cast<Eigen::Index>(guide.jaw_move.size());
  const std::int64_t frames = timeline.frame_count() - timeline.phones.front().first_frame;
  if (pca_frames.cols() != k || static_cast<Eigen::Index>(guide.chin_drop.size()) != k || pca_frames.rows() != frames)
    throw std::invalid_argument("level_jaw: " + std::to_string(pca_frames.rows()) + " x " + std::to_string(pca_frames.cols()) +
                                " frames for a timeline of " + std::to_string(frames) + " frames and " + std::to_string(k) +
                                " coefficients");
  const std::vector<double> wanted = wanted_jaw_frames(guide, timeline, cutoff_hz);
  std::vector<double> opening(static_cast<std::size_t>(frames));
  for (Eigen::Index n = 0; n < pca_frames.rows(); ++n) opening[static_cast<std::size_t>(n)] = frame_opening(guide, pca_frames.row(n));
  // The same filter on both sides: what is left of the units' jaw above the cut-off is theirs.
  const std::vector<double> slow = opening.size() < 3 ? opening : zero_phase_lowpass(opening, static_cast<double>(kVoiceFramesPerSecond), cutoff_hz);
  const auto move = Eigen::Map<const Eigen::RowVectorXf>(guide.jaw_move.data(), k);
  for (Eigen::Index n = 0; n < pca_frames.rows(); ++n) {
    const auto i = static_cast<std::size_t>(n);
    pca_frames.row(n) += static_cast<float>(strength * (wanted[i] - slow[i])) * move;
  }
}

}  // namespace fapcast
