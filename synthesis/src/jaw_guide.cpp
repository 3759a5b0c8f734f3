#include "fapcast/synthesis/jaw_guide.hpp"

#include "fapcast/math/zero_phase_lowpass.hpp"

#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <initializer_list>

namespace fapcast {
namespace {

// The jaw's own move: a coefficient change that lowers the front of the mandible - the chin 2.1,
// the chin boss 2.10 and the chin's corners 2.11, 2.12 - by `drop_m` while the lips keep their
// shape (as far as the face's likely moves allow, below): the aperture (8.1 - 8.2 vertically), the mouth's width (8.3 - 8.4), the heights of the
// upper lip (8.1) and of the corners (8.3, 8.4) and both lips' protrusion (8.1, 8.2 forwards).
// The lips trade with the jaw so as to keep the opening speech needs (motor equivalence,
// spec/synthesis.md, "The jaw's level"). Chin points the voice lacks drop their rows; empty when
// the voice lacks the lips or no likely move lowers the chin.
std::vector<float> jaw_move_of(const Voice& voice, const Eigen::VectorXf& chin_drop, double drop_m) {
  const auto points = voice.feature_points();
  const auto vertex = [&](const char* label) -> Eigen::Index {
    for (const VoiceFeaturePoint& p : points)
      if (p.label == label) return p.vertex;
    return -1;
  };
  const auto components = voice.pca_components();
  const Eigen::Index k = components.rows();
  const auto axis = [&](Eigen::Index v, int a) -> Eigen::VectorXd { return components.col(3 * v + a).cast<double>(); };
  std::vector<Eigen::VectorXd> rows{chin_drop.cast<double>()};
  std::vector<double> wanted{drop_m};
  for (const char* label : {"2.10", "2.11", "2.12"})
    if (const Eigen::Index v = vertex(label); v >= 0) rows.push_back(-axis(v, 1)), wanted.push_back(drop_m);
  const Eigen::Index upper = vertex("8.1"), lower = vertex("8.2"), left = vertex("8.3"), right = vertex("8.4");
  if (upper < 0 || lower < 0 || left < 0 || right < 0) return {};
  for (const Eigen::VectorXd& held : {Eigen::VectorXd(axis(upper, 1) - axis(lower, 1)), Eigen::VectorXd(axis(left, 0) - axis(right, 0)),
                                     axis(upper, 1), axis(left, 1), axis(right, 1), axis(upper, 2), axis(lower, 2)})
    rows.push_back(held), wanted.push_back(0.0);
  Eigen::MatrixXd a(static_cast<Eigen::Index>(rows.size()), k);
  for (std::size_t i = 0; i < rows.size(); ++i) a.row(static_cast<Eigen::Index>(i)) = rows[i].transpose();
  // The prior: each coefficient's variance over the corpus (the PCA's own), so that a move the
  // talker makes often costs less than one the talker seldom makes.
  const Eigen::VectorXd variance = voice.pca_variances().row(0).transpose().cast<double>();
  if (variance.size() != k || !(variance.array() > 0).all()) return {};
  // The least-squares move in units of the talker's own spread (u = c / sd), shortest first: the
  // pseudo-inverse of the constraints over those units, keeping the directions at least a tenth as
  // strong as the strongest. The full system asks for moves the talker never makes (tens of
  // standard deviations of its weakest components per millimetre of jaw, and a face whose
  // symmetric rows depend on one another has an exactly singular one), so the lips are held as far
  // as the face's likely moves allow, not exactly (spec/synthesis.md, "The jaw's level").
  const Eigen::VectorXd sd = variance.cwiseSqrt();
  const Eigen::VectorXd b = Eigen::Map<const Eigen::VectorXd>(wanted.data(), static_cast<Eigen::Index>(wanted.size()));
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(a * sd.asDiagonal(), Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd strength = svd.singularValues();
  Eigen::VectorXd inverse = Eigen::VectorXd::Zero(strength.size());
  for (Eigen::Index i = 0; i < strength.size(); ++i)
    if (strength[i] >= 0.1 * strength[0] && strength[i] > 0) inverse[i] = 1.0 / strength[i];
  Eigen::VectorXd move = sd.asDiagonal() * (svd.matrixV() * (inverse.asDiagonal() * (svd.matrixU().transpose() * b)));
  // Scaled so that the move opens the chin by exactly `drop_m`: level 1 is then the wanted jaw.
  const double chin = rows.front().dot(move);
  if (!move.allFinite() || !(chin > 0.1 * drop_m)) return {};
  move *= drop_m / chin;
  return {move.data(), move.data() + move.size()};
}

}  // namespace

JawGuide make_jaw_guide(const Voice& voice) {
  const auto points = voice.feature_points();
  const auto chin = std::find_if(points.begin(), points.end(), [](const VoiceFeaturePoint& p) { return p.label == "2.1"; });
  if (chin == points.end())
    throw InputError(InputLocation{voice.file().source(), {}, {}}, "jaw-guide",
                     "the voice has no chin feature point (FP 2.1), which the jaw term measures");
  const Eigen::Index y = 3 * static_cast<Eigen::Index>(chin->vertex) + 1;
  const auto components = voice.pca_components();
  Eigen::VectorXf down(components.rows());  // chin travel downwards per unit of each coefficient, metres
  for (Eigen::Index c = 0; c < components.rows(); ++c) down[c] = -components(c, y);
  const auto frames = voice.frame_coefficients();
  const Eigen::VectorXf opening = frames * down;  // per frame, metres below the mean face

  const PhoneGraph& graph = voice.graph();
  const auto phones = voice.state_phones();
  JawGuide guide;
  guide.state_opening.resize(graph.size());
  std::array<double, kPhoneCount> sum{};
  std::array<std::size_t, kPhoneCount> count{};
  double speech_sum = 0.0, speech_square = 0.0;
  std::size_t speech = 0;
  for (StateId j = 0; j < graph.size(); ++j) {
    const FrameSpan span = graph.state(j).frames;
    const double mean = span.count == 0 ? 0.0 : opening.segment(span.first, span.count).cast<double>().mean();
    guide.state_opening[j] = static_cast<float>(mean);
    const auto p = static_cast<std::size_t>(phones[j]);
    sum[p] += mean, ++count[p];
    if (graph.state(j).viseme != VisemeClass::kSilence) speech_sum += mean, speech_square += mean * mean, ++speech;
  }
  const double centre = speech == 0 ? 0.0 : speech_sum / static_cast<double>(speech);
  const double spread = speech < 2 ? 0.0 : std::sqrt(std::max(0.0, speech_square / static_cast<double>(speech) - centre * centre));
  if (!(spread > 1e-6))  // a micrometre: a still chin gives the search nothing to follow
    throw InputError(InputLocation{voice.file().source(), {}, {}}, "jaw-guide",
                     "the chin (FP 2.1) does not move across the voice's phones: the jaw term has nothing to follow");
  for (float& v : guide.state_opening) v = static_cast<float>((v - centre) / spread);
  for (std::size_t p = 0; p < kPhoneCount; ++p)
    guide.phone_opening[p] = count[p] == 0 ? 0.0f : static_cast<float>((sum[p] / static_cast<double>(count[p]) - centre) / spread);
  guide.spread_mm = 1000.0 * spread;
  guide.centre_mm = 1000.0 * centre;
  guide.chin_drop.assign(down.data(), down.data() + down.size());
  guide.jaw_move = jaw_move_of(voice, down, spread);
  return guide;
}

double frame_opening(const JawGuide& guide, const Eigen::Ref<const Eigen::RowVectorXf>& c) {
  const auto drop = Eigen::Map<const Eigen::VectorXf>(guide.chin_drop.data(), static_cast<Eigen::Index>(guide.chin_drop.size()));
  return (1000.0 * static_cast<double>(c.dot(drop)) - guide.centre_mm) / guide.spread_mm;
}

std::vector<double> wanted_jaw_frames(const JawGuide& guide, const TargetTimeline& timeline, double cutoff_hz) {
  const auto& targets = timeline.phones;
  if (targets.empty()) return {};
  const std::int64_t first = targets.front().first_frame;
  std::vector<double> laid(static_cast<std::size_t>(timeline.frame_count() - first));
  for (std::size_t t = 0; t < targets.size(); ++t)
    for (std::int64_t n = targets[t].first_frame; n < targets[t].end_frame; ++n)
      laid[static_cast<std::size_t>(n - first)] = guide.phone_opening[static_cast<std::size_t>(timeline.phone_of[t])];
  return laid.size() < 3 ? laid : zero_phase_lowpass(laid, static_cast<double>(kVoiceFramesPerSecond), cutoff_hz);
}

std::vector<float> wanted_jaw(const JawGuide& guide, const TargetTimeline& timeline, double cutoff_hz) {
  const auto& targets = timeline.phones;
  if (targets.empty()) return {};
  const std::int64_t first = targets.front().first_frame;
  const std::vector<double> smooth = wanted_jaw_frames(guide, timeline, cutoff_hz);
  std::vector<float> out(targets.size());
  for (std::size_t t = 0; t < targets.size(); ++t) {
    double s = 0.0;
    for (std::int64_t n = targets[t].first_frame; n < targets[t].end_frame; ++n) s += smooth[static_cast<std::size_t>(n - first)];
    out[t] = static_cast<float>(s / static_cast<double>(std::max<std::int64_t>(1, targets[t].end_frame - targets[t].first_frame)));
  }
  return out;
}

}  // namespace fapcast
