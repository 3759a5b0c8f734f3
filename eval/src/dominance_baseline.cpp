#include "fapcast/eval/dominance_baseline.hpp"

#include "fapcast/math/dominance.hpp"

#include <stdexcept>
#include <string>

namespace fapcast {

VisemeTargets viseme_targets(const PhoneGraph& graph, const PcaFrames& pca_frames) {
  VisemeTargets out;
  out.coefficients = Eigen::MatrixXf::Zero(static_cast<Eigen::Index>(kVisemeClassCount), pca_frames.cols());
  out.phones.assign(kVisemeClassCount, 0);
  Eigen::MatrixXd sums = Eigen::MatrixXd::Zero(out.coefficients.rows(), out.coefficients.cols());
  for (const auto& s : graph.states()) {
    if (s.frames.count == 0) continue;
    const Eigen::Index centre = Eigen::Index{s.frames.first} + s.frames.count / 2;
    if (centre >= pca_frames.rows())
      throw std::invalid_argument("viseme targets: a phone's frames lie beyond the " +
                                  std::to_string(pca_frames.rows()) + " PCA frames");
    const auto v = static_cast<Eigen::Index>(s.viseme);
    sums.row(v) += pca_frames.row(centre).cast<double>();
    ++out.phones[static_cast<std::size_t>(v)];
  }
  for (Eigen::Index v = 0; v < sums.rows(); ++v)
    if (out.phones[static_cast<std::size_t>(v)] > 0)
      out.coefficients.row(v) = (sums.row(v) / out.phones[static_cast<std::size_t>(v)]).cast<float>();
  return out;
}

const Dominance& baseline_dominance(VisemeClass v, const DominanceBaselineOptions& options) {
  switch (v) {
    case VisemeClass::kBilabial:
    case VisemeClass::kLabiodental: return options.contact;
    case VisemeClass::kSilence: return options.silence;
    default: return options.phone;
  }
}

Eigen::MatrixXf dominance_interpolation(const VisemeTargets& targets,
                                        std::span<const TargetPhone> phones,
                                        const DominanceBaselineOptions& options) {
  if (options.frame_rate_hz <= 0) throw std::invalid_argument("dominance baseline: frame rate must be positive");
  if (phones.empty()) return Eigen::MatrixXf(0, targets.coefficients.cols());
  for (std::size_t t = 0; t < phones.size(); ++t) {
    const auto where = "dominance baseline: target phone " + std::to_string(t);
    if (phones[t].end_frame <= phones[t].first_frame) throw std::invalid_argument(where + " spans no frames");
    if (t > 0 && phones[t].first_frame < phones[t - 1].end_frame)
      throw std::invalid_argument(where + " starts before the previous one ends");
    if (targets.phones.at(static_cast<std::size_t>(phones[t].viseme)) == 0)
      throw std::invalid_argument(where + ": the voice has no phone of viseme class '" +
                                  std::string(viseme_class_name(phones[t].viseme)) + "'");
  }
  const std::int64_t origin = phones.front().first_frame;
  const std::int64_t frames = phones.back().end_frame - origin;
  const double fps = options.frame_rate_hz;
  const Eigen::Index k = targets.coefficients.cols();
  Eigen::MatrixXf out(static_cast<Eigen::Index>(frames), k);
  DominanceBlend blend(static_cast<std::size_t>(k));
  for (std::int64_t n = 0; n < frames; ++n) {
    const double t_s = static_cast<double>(origin + n) / fps;
    blend.clear();
    for (const auto& p : phones) {
      // The mean time of the phone's frames: they are shown at or after its start, so their span's
      // own middle, (first + end) / 2, would lie half a frame after the phone's middle on average.
      const double centre_s = 0.5 * static_cast<double>(p.first_frame + p.end_frame - 1) / fps;
      const double d = baseline_dominance(p.viseme, options).at(t_s - centre_s);
      const auto target = targets.coefficients.row(static_cast<Eigen::Index>(p.viseme));
      for (Eigen::Index c = 0; c < k; ++c) blend.add(static_cast<std::size_t>(c), d, target(c));
    }
    // exp() underflows only for a frame ~50 s from every phone, which cannot happen inside the
    // span; the blend is 0 there rather than a division by zero.
    for (Eigen::Index c = 0; c < k; ++c)
      out(static_cast<Eigen::Index>(n), c) = static_cast<float>(blend.value(static_cast<std::size_t>(c)));
  }
  return out;
}

}  // namespace fapcast
