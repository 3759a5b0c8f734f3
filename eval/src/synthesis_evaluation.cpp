#include "fapcast/eval/synthesis_evaluation.hpp"

#include "fapcast/eval/held_out_sentences.hpp"
#include "fapcast/eval/trajectory_agreement.hpp"
#include "fapcast/core/portable_random.hpp"
#include "fapcast/corpus/recording_script.hpp"
#include "fapcast/talker/reference_talker.hpp"
#include "fapcast/synthesis/synthesis.hpp"
#include "fapcast/voice/voice_frame_grid.hpp"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <stdexcept>

namespace fapcast {
namespace {

// Lip curves of vertex tracks (metres) in millimetres.
LipCurves curves_mm(const Eigen::MatrixXf& tracks, const EvaluationPoints& points) {
  return lip_curves(Eigen::MatrixXf(1000.0f * tracks), points.lip_measure);
}

// The targets with every class the voice lacks replaced, as synthesize() does.
std::vector<TargetPhone> covered(const PhoneGraph& graph, std::span<const TargetPhone> targets) {
  std::vector<TargetPhone> out(targets.begin(), targets.end());
  for (auto& t : out) t.viseme = covered_viseme(graph, t.viseme);
  return out;
}

}  // namespace

std::vector<HeldOutUtterance> record_held_out(const FaceModel& actor, std::uint64_t seed,
                                              std::size_t count) {
  PortableRandom master(seed);
  std::vector<HeldOutUtterance> out;
  for (std::size_t i = 0; i < std::min(count, kHeldOutSentences.size()); ++i) {
    char id[32];
    std::snprintf(id, sizeof id, "heldout%02zu", i + 1);
    PortableRandom random = master.split();
    const ScriptItem item{ScriptSection::kCommonWord, std::string(kHeldOutSentences[i]), {}, "", 0.0};
    ReferenceTake take = record_take(item, id, actor, random);
    HeldOutUtterance u;
    u.id = id;
    u.text = item.text;
    u.targets = place_on_voice_grid(take.speech.phones, take.speech.audio.sample_rate,
                                    static_cast<std::int64_t>(take.speech.audio.samples.size()), id)
                    .phones;
    u.speech = std::move(take.speech);
    u.recorded = std::move(take.clean);
    out.push_back(std::move(u));
  }
  return out;
}

NamedSystem diviseme_system(const PhoneGraph& graph, Eigen::Map<const RowMajorMatrixXf> pca_frames,
                            ConcatenationOptions options, DivisemeChoiceRule rule) {
  return {rule == DivisemeChoiceRule::kFirst ? "diviseme-first" : "diviseme",
          [&graph, pca_frames, options, rule](const HeldOutUtterance& u) {
            const auto targets = covered(graph, u.targets);
            const auto selection = select_divisemes(graph, targets, rule);
            return SystemOutput{concatenate_divisemes(graph, pca_frames, selection, targets, options),
                                selection.divisemes.size() + selection.unrecorded};
          }};
}

NamedSystem dominance_system(const PhoneGraph& graph, const PcaFrames& pca_frames,
                             DominanceBaselineOptions options) {
  // Targets once, not per utterance.
  auto targets = std::make_shared<VisemeTargets>(viseme_targets(graph, pca_frames));
  return {"dominance", [&graph, targets, options](const HeldOutUtterance& u) {
            return SystemOutput{dominance_interpolation(*targets, covered(graph, u.targets), options), 0};
          }};
}

EvaluationReport evaluate_synthesis(const EvaluationFace& face, std::span<const NamedSystem> systems,
                                    std::span<const HeldOutUtterance> utterances) {
  if (face.pca_mean.rows() != 1 || face.pca_components.cols() != face.pca_mean.cols() ||
      face.retarget_map == nullptr || !face.source_vectors)
    throw std::invalid_argument("synthesis evaluation: the face lacks its PCA basis, map or source vectors");
  const auto& vertices = face.points.vertices;
  std::vector<SynthesisScorer> scorers(systems.size(), SynthesisScorer(face.points));
  std::vector<std::size_t> units(systems.size(), 0);
  EvaluationReport report;
  for (const auto& u : utterances) {
    const Eigen::MatrixXf recorded = vertex_tracks(*face.retarget_map, face.source_vectors(u.recorded), vertices);
    UtteranceCurves curves{u.id, u.text, curves_mm(recorded, face.points), {}};
    for (std::size_t s = 0; s < systems.size(); ++s) {
      SystemOutput out;
      try {
        out = systems[s].synthesise(u);
      } catch (...) {
        std::throw_with_nested(std::runtime_error("system '" + systems[s].name + "' on " + u.id));
      }
      if (out.coefficients.cols() != face.pca_components.rows())
        throw std::invalid_argument("synthesis evaluation: system '" + systems[s].name + "' made " +
                                    std::to_string(out.coefficients.cols()) + " coefficients per frame, the face has " +
                                    std::to_string(face.pca_components.rows()));
      Eigen::MatrixXf tracks = vertex_tracks(face.pca_mean, face.pca_components, out.coefficients, vertices);
      // Systems start at the first target frame; the recording at frame 0: hold the first frame.
      const std::int64_t lead = u.targets.empty() ? 0 : u.targets.front().first_frame;
      if (lead > 0 && tracks.rows() > 0) {
        Eigen::MatrixXf padded(tracks.rows() + lead, tracks.cols());
        padded.topRows(lead).rowwise() = tracks.row(0);
        padded.bottomRows(tracks.rows()) = tracks;
        tracks = std::move(padded);
      }
      scorers[s].add(recorded, tracks);
      curves.synthesised.push_back(curves_mm(tracks, face.points));
      units[s] += out.units;
    }
    report.phones += u.targets.size();
    report.frames += static_cast<std::size_t>(recorded.rows());
    report.utterances.push_back(std::move(curves));
  }
  for (std::size_t s = 0; s < systems.size(); ++s)
    report.systems.push_back({systems[s].name, scorers[s].score(),
                              report.phones > 0 ? static_cast<double>(units[s]) / static_cast<double>(report.phones) : 0.0});
  return report;
}

std::optional<double> median_lip_height_lag_ms(const EvaluationReport& report, std::size_t system) {
  std::vector<double> lags;
  for (const UtteranceCurves& u : report.utterances) {
    if (system >= u.synthesised.size()) throw std::out_of_range("lip height lag: no such system");
    const std::size_t n = std::min(u.recorded.height.size(), u.synthesised[system].height.size());
    if (n < 3) continue;
    const std::span<const double> recorded(u.recorded.height.data(), n), synthesised(u.synthesised[system].height.data(), n);
    lags.push_back(1000.0 * trajectory_agreement(recorded, synthesised, static_cast<double>(kVoiceFramesPerSecond), 0.1, 0.001).best_lag_s);
  }
  if (lags.empty()) return std::nullopt;
  const auto middle = lags.begin() + static_cast<std::ptrdiff_t>(lags.size() / 2);
  std::nth_element(lags.begin(), middle, lags.end());
  if (lags.size() % 2 == 1) return *middle;
  return 0.5 * (*middle + *std::max_element(lags.begin(), middle));
}

}  // namespace fapcast
