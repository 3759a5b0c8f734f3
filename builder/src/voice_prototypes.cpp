#include "fapcast/builder/voice_prototypes.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <array>
#include <limits>
#include <stdexcept>
#include <string>

#include "fapcast/core/tsv_table.hpp"
#include "fapcast/talker/coarticulation.hpp"
#include "fapcast/voice/voice_frame_grid.hpp"

namespace fapcast {
namespace {

// spec/prototypes.tsv, row for row: the details added to the realised articulation.
constexpr PrototypeShapeWeight kDetails[] = {
    {VisemeClass::kSilence, "mouthClose", 0.058f},
    {VisemeClass::kBilabial, "mouthRollUpper", 0.15f},
    {VisemeClass::kBilabial, "mouthRollLower", 0.1f},
    {VisemeClass::kLabiodental, "noseSneer_L", 0.1f},
    {VisemeClass::kLabiodental, "noseSneer_R", 0.1f},
    {VisemeClass::kDental, "mouthLowerDown_L", 0.1f},
    {VisemeClass::kDental, "mouthLowerDown_R", 0.1f},
    {VisemeClass::kDental, "jawForward", 0.1f},
    {VisemeClass::kAlveolar, "mouthPress_L", 0.1f},
    {VisemeClass::kAlveolar, "mouthPress_R", 0.1f},
    {VisemeClass::kSibilant, "jawForward", 0.15f},
    {VisemeClass::kSibilant, "mouthDimple_L", 0.15f},
    {VisemeClass::kSibilant, "mouthDimple_R", 0.15f},
    {VisemeClass::kLateral, "mouthUpperUp_L", 0.06f},
    {VisemeClass::kLateral, "mouthUpperUp_R", 0.06f},
    {VisemeClass::kPostalveolar, "mouthFunnel", 0.2f},
    {VisemeClass::kPostalveolar, "mouthShrugUpper", 0.2f},
    {VisemeClass::kRhotic, "mouthPucker", 0.1f},
    {VisemeClass::kRhotic, "mouthRollLower", 0.1f},
    {VisemeClass::kLabialVelar, "mouthPucker", 0.15f},
    {VisemeClass::kLabialVelar, "mouthShrugLower", 0.2f},
    {VisemeClass::kLabialVelar, "mouthRollLower", 0.1f},
    {VisemeClass::kCloseFront, "cheekSquint_L", 0.15f},
    {VisemeClass::kCloseFront, "cheekSquint_R", 0.15f},
    {VisemeClass::kNearCloseFront, "mouthDimple_L", 0.05f},
    {VisemeClass::kNearCloseFront, "mouthDimple_R", 0.05f},
    {VisemeClass::kMidFront, "cheekSquint_L", 0.05f},
    {VisemeClass::kMidFront, "cheekSquint_R", 0.05f},
    {VisemeClass::kOpenFront, "mouthStretch_L", 0.15f},
    {VisemeClass::kOpenFront, "mouthStretch_R", 0.15f},
    {VisemeClass::kOpenUnrounded, "mouthFrown_L", 0.1f},
    {VisemeClass::kOpenUnrounded, "mouthFrown_R", 0.1f},
    {VisemeClass::kOpenMidRounded, "mouthFunnel", 0.15f},
    {VisemeClass::kMidRounded, "mouthFunnel", 0.1f},
    {VisemeClass::kNearCloseRounded, "mouthFunnel", 0.1f},
    {VisemeClass::kCloseRounded, "mouthShrugLower", 0.1f},
};

}  // namespace

std::span<const PrototypeShapeWeight> target_prototype_details() { return kDetails; }

std::vector<PrototypeSpecRow> read_prototype_spec(const std::filesystem::path& file) {
  std::vector<PrototypeSpecRow> out;
  for (const auto& row : read_tsv(file, 4))
    out.push_back({row.fields[0], row.fields[1], tsv_float(file, row, 2), row.fields[3]});
  return out;
}

void RealisedArticulation::add_take(std::span<const Phone> phones, std::span<const FrameSpan> spans) {
  if (phones.size() != spans.size())
    throw std::invalid_argument("realised articulation: " + std::to_string(phones.size()) + " phones, " +
                                std::to_string(spans.size()) + " spans");
  // The take on the voice grid's own clock: one sample per frame, so a segment's centre frame is
  // at t = (first + count / 2) / 60 s.
  PhoneTimeline timeline{SampleRate{static_cast<std::int64_t>(kVoiceFramesPerSecond)}, {}};
  for (std::size_t s = 0; s < phones.size(); ++s) {
    const FrameSpan span = spans[s];
    timeline.phones.push_back({phones[s], span.first, static_cast<std::int64_t>(span.first) + span.count});
  }
  validate_timeline(timeline);
  for (std::size_t s = 0; s < phones.size(); ++s) {
    const double centre = static_cast<double>(centre_frame(spans[s])) / kVoiceFramesPerSecond;
    const ChannelValues v = channel_values_at(timeline, centre);
    const auto c = static_cast<std::size_t>(search_viseme(phones[s]));
    for (std::size_t k = 0; k < kChannelCount; ++k) sum_[c][k] += std::clamp(v[k], 0.0f, 1.0f);
    ++count_[c];
  }
}

ChannelValues RealisedArticulation::mean(VisemeClass v) const {
  const auto c = static_cast<std::size_t>(v);
  if (count_[c] == 0)
    throw std::invalid_argument("realised articulation: no segment of class " + std::string(viseme_class_name(v)));
  ChannelValues out{};
  for (std::size_t k = 0; k < kChannelCount; ++k) out[k] = static_cast<float>(sum_[c][k] / static_cast<double>(count_[c]));
  return out;
}

ChannelValues nominal_class_channels(VisemeClass v) {
  ChannelValues mean{};
  int phones = 0;
  for (const auto& row : kVisemeTable) {
    if (row.search_class != v) continue;
    const PhoneArticulation& a = phone_articulation(row.phone);
    for (std::size_t c = 0; c < kChannelCount; ++c) mean[c] += a.target[c];
    ++phones;
  }
  for (auto& x : mean) x /= static_cast<float>(phones);
  return mean;
}

std::vector<float> target_prototype_weights(const FaceModel& face, VisemeClass v, const ChannelValues& channels) {
  std::vector<float> weights = ShapeMapper(face)(channels);
  for (const PrototypeShapeWeight& row : kDetails)
    if (row.viseme == v) weights[face.expression_index(row.shape)] += row.weight;
  for (float& w : weights) w = std::clamp(w, 0.0f, 1.0f);
  return weights;
}

Eigen::MatrixXd target_prototype_meshes(const FaceModel& face, std::span<const VisemeClass> classes,
                                        std::span<const ChannelValues> channels) {
  if (classes.size() != channels.size())
    throw std::invalid_argument("target prototypes: " + std::to_string(classes.size()) + " classes, " +
                                std::to_string(channels.size()) + " channel vectors");
  const Eigen::Index n = face.vertex_count();
  Eigen::MatrixXd out(static_cast<Eigen::Index>(classes.size()), 3 * n);
  for (std::size_t c = 0; c < classes.size(); ++c) {
    const std::vector<float> weights = target_prototype_weights(face, classes[c], channels[c]);
    Positions mesh = face.neutral_cm;
    for (std::size_t s = 0; s < weights.size(); ++s)
      if (weights[s] != 0.0f) add_scaled(mesh, face.expressions[s], weights[s]);
    // Positions is 3 x N column-major: its storage is already x y z per vertex.
    out.row(static_cast<Eigen::Index>(c)) =
        Eigen::Map<const Eigen::RowVectorXf>(mesh.data(), 3 * n).cast<double>() / 100.0;
  }
  return out;
}

Eigen::Index centred_rank(const Eigen::MatrixXd& rows, double relative_tolerance) {
  if (rows.rows() < 2) return 0;
  const Eigen::MatrixXd centred = rows.rowwise() - rows.colwise().mean();
  // The rows are few (21) and long (D): their singular values are the square roots of the
  // small Gram matrix's (squaring the condition is harmless at the tolerances used here).
  const Eigen::MatrixXd gram = centred * centred.transpose();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(gram);
  const Eigen::VectorXd s = svd.singularValues().cwiseMax(0.0).cwiseSqrt();
  if (s.size() == 0 || s(0) == 0) return 0;
  Eigen::Index rank = 0;
  for (Eigen::Index i = 0; i < s.size(); ++i)
    if (s(i) > relative_tolerance * s(0)) ++rank;
  return rank;
}

std::vector<SourcePrototype> select_source_prototypes(const Eigen::MatrixXd& frames,
                                                      std::span<const PhoneState> states) {
  const Eigen::Index d = frames.rows();
  std::array<Eigen::VectorXd, kVisemeClassCount> sum;
  std::array<std::size_t, kVisemeClassCount> count{};
  for (auto& s : sum) s = Eigen::VectorXd::Zero(d);
  for (std::size_t j = 0; j < states.size(); ++j) {
    const PhoneState& s = states[j];
    if (s.frames.count == 0 ||
        static_cast<Eigen::Index>(s.frames.first) + static_cast<Eigen::Index>(s.frames.count) > frames.cols())
      throw std::invalid_argument("select_source_prototypes: state " + std::to_string(j) +
                                  " spans frames outside the " + std::to_string(frames.cols()) + " given");
    const auto v = static_cast<std::size_t>(s.viseme);
    sum[v] += frames.col(centre_frame(s));
    ++count[v];
  }
  std::array<double, kVisemeClassCount> best_distance;
  best_distance.fill(std::numeric_limits<double>::infinity());
  std::array<Eigen::Index, kVisemeClassCount> best_frame{};
  std::array<Eigen::VectorXd, kVisemeClassCount> mean;
  for (std::size_t v = 0; v < kVisemeClassCount; ++v)
    if (count[v] > 0) mean[v] = sum[v] / static_cast<double>(count[v]);
  for (const PhoneState& s : states) {
    const auto v = static_cast<std::size_t>(s.viseme);
    const Eigen::Index f = centre_frame(s);
    const double distance = (frames.col(f) - mean[v]).squaredNorm();
    if (distance < best_distance[v] || (distance == best_distance[v] && f < best_frame[v])) {
      best_distance[v] = distance;
      best_frame[v] = f;
    }
  }
  std::vector<SourcePrototype> out;
  for (std::size_t v = 0; v < kVisemeClassCount; ++v)
    if (count[v] > 0) out.push_back({static_cast<VisemeClass>(v), best_frame[v], count[v]});
  return out;
}

}  // namespace fapcast
