#include "fapcast/builder/voice_build.hpp"

#include <chrono>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "fapcast/math/affine_image_pca.hpp"
#include "fapcast/math/em_pca.hpp"
#include "fapcast/face/face_model.hpp"
#include "fapcast/core/input_error.hpp"
#include "fapcast/face/marker_map.hpp"
#include "fapcast/capture/preprocessing.hpp"
#include "fapcast/math/rbf_retarget.hpp"
#include "fapcast/math/running_moments.hpp"
#include "fapcast/voice/voice.hpp"
#include "fapcast/builder/voice_corpus.hpp"
#include "fapcast/voice/voice_file.hpp"
#include "fapcast/voice/voice_graph.hpp"
#include "fapcast/builder/voice_prototypes.hpp"
#include "fapcast/builder/lip_contact_fit.hpp"
#include "fapcast/voice/lip_contact.hpp"

namespace fapcast {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The corpus as the build holds it: every source frame (d x F, metres, ~50 MB for 60,000 frames)
// and the phone graph's raw arrays.
struct SourceCorpus {
  Eigen::MatrixXd frames;
  VoiceGraphData graph;
  Eigen::Matrix3Xd rigid_reference_cm;
  RealisedArticulation articulation;  // the target prototypes' articulation part
  bool synthetic = false;
  std::size_t pattern_filled_gaps = 0;
};

SourceCorpus read_source_corpus(const CorpusListing& listing, const VoiceBuildOptions& options) {
  SourceCorpus corpus;
  corpus.synthetic = listing.synthetic;
  std::vector<Eigen::MatrixXd> parts;
  std::uint32_t total = 0;
  const std::size_t n = listing.utterances.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::string source = listing.utterances[i].markers.string();
    CorpusTake take = read_corpus_take(listing, i);
    if (i == 0) corpus.rigid_reference_cm = corpus_rigid_reference(take, source);
    corpus.synthetic = corpus.synthetic || take.synthetic;
    const PreprocessedTake stabilised = preprocess_take(take.markers, rigid_marker_rows(), corpus.rigid_reference_cm);
    corpus.pattern_filled_gaps += stabilised.pattern_filled.size();
    parts.push_back(source_vectors_m(stabilised.frames, source));
    corpus.articulation.add_take(take.phones, take.spans);
    const auto frames = static_cast<std::uint32_t>(parts.back().cols());
    const auto utterance = static_cast<std::uint32_t>(i);
    for (std::size_t s = 0; s < take.phones.size(); ++s) {
      corpus.graph.states.push_back({utterance, search_viseme(take.phones[s]),
                                     {total + take.spans[s].first, take.spans[s].count}});
      corpus.graph.phones.push_back(take.phones[s]);
    }
    corpus.graph.utterances.push_back({total, frames});
    total += frames;
    if (options.progress) options.progress("read", i + 1, n);
  }
  corpus.graph.frame_count = total;
  corpus.frames.resize(parts.front().rows(), total);
  Eigen::Index at = 0;
  for (Eigen::MatrixXd& part : parts) {
    corpus.frames.middleCols(at, part.cols()) = part;
    at += part.cols();
    part = Eigen::MatrixXd();  // keep the peak near one copy
  }
  return corpus;
}

RowMajorMatrixXf row_f(const Eigen::VectorXd& v) { return v.transpose().cast<float>(); }

}  // namespace

std::string_view pca_route_name(PcaRoute route) { return route == PcaRoute::exact ? "exact" : "em"; }

BuiltVoice build_voice(const std::filesystem::path& corpus_dir, const VoiceBuildOptions& options) {
  const auto start = Clock::now();
  const int k = options.components;
  if (k < 1) throw std::invalid_argument("voice build: k = " + std::to_string(k) + " components, need at least 1");
  const CorpusListing listing = list_corpus(corpus_dir);
  const FaceModel& face = ict_face_model();
  BuiltVoice out;
  VoiceBuildSummary& summary = out.summary;

  // 3.3: every take, preprocessed, as source vectors; the phone states on the frame grid.
  SourceCorpus corpus = read_source_corpus(listing, options);
  const Eigen::Index frames = corpus.frames.cols();
  summary.pattern_filled_gaps = corpus.pattern_filled_gaps;
  summary.seconds_read = since(start);

  // 3.4-3.5: prototypes, r^2 over all frames, the RBF map with GCV's lambda.
  const auto fit_start = Clock::now();
  RunningSpread spread(corpus.frames.rows());
  for (Eigen::Index f = 0; f < frames; ++f) spread.add(corpus.frames.col(f));
  const double r_squared = spread.mean_squared_distance();
  const std::vector<SourcePrototype> prototypes = select_source_prototypes(corpus.frames, corpus.graph.states);
  const auto m = static_cast<Eigen::Index>(prototypes.size());
  std::vector<VisemeClass> classes;
  std::vector<ChannelValues> realised;
  Eigen::MatrixXd centres(m, corpus.frames.rows());
  for (Eigen::Index i = 0; i < m; ++i) {
    classes.push_back(prototypes[static_cast<std::size_t>(i)].viseme);
    realised.push_back(corpus.articulation.mean(classes.back()));
    centres.row(i) = corpus.frames.col(prototypes[static_cast<std::size_t>(i)].frame).transpose();
  }
  const Eigen::MatrixXd targets = target_prototype_meshes(face, classes, realised);
  summary.target_rank = centred_rank(targets);
  if (summary.target_rank < k || !(r_squared > 0))
    throw InputError({corpus_dir.string(), std::nullopt, std::nullopt}, "voice-prototypes",
                     "the corpus covers " + std::to_string(m) + " of 21 viseme classes; their target prototypes have centred rank " +
                         std::to_string(summary.target_rank) + ", fewer than k = " + std::to_string(k) +
                         " components (or every frame is the same)");
  LambdaChoice choice;
  const RbfMap map = fit_rbf_by_gcv(centres, targets, r_squared, &choice);
  // The lip-contact term, measured against the bilabial target prototype (spec/voice.md).
  std::optional<LipContact> contact;
  for (Eigen::Index i = 0; i < m; ++i)
    if (classes[static_cast<std::size_t>(i)] == VisemeClass::kBilabial)
      contact = fit_lip_contact(face, map, corpus.frames, corpus.graph.states, targets.row(i).transpose());
  const Retargeting retarget(map, contact);
  if (contact) {
    summary.lip_contact = true;
    summary.source_contact_m = contact->source_contact_m;
    summary.target_contact_m = contact->target_contact_m;
  }
  summary.seconds_fit = since(fit_start);
  if (options.progress) options.progress("fit", 1, 1);

  // 3.6: the PCA of the retargeted corpus. The responses (m (+1) x F) serve both routes' coefficients.
  const auto pca_start = Clock::now();
  Eigen::MatrixXd responses(retarget.response_count(), frames);
  for (Eigen::Index f = 0; f < frames; ++f) responses.col(f) = retarget.responses(corpus.frames.col(f));
  if (contact) summary.lip_contact_frames = (responses.bottomRows(1).array() > 0).count();
  PcaBasis basis;
  if (options.pca == PcaRoute::exact) {
    RunningCovariance covariance(retarget.response_count());
    for (Eigen::Index f = 0; f < frames; ++f) covariance.add(responses.col(f));
    basis = pca_of_affine_image(retarget.weights(), retarget.offset(), covariance.mean(), covariance.covariance(), k);
  } else {
    FrameStream stream{frames, map.target_dimension(), [&](Eigen::Index first, Eigen::Ref<Eigen::MatrixXf> chunk) {
                         retarget.map_columns(corpus.frames.middleCols(first, chunk.cols()), chunk);
                       }};
    EmPcaOptions em;
    em.components = k;
    em.seed = options.seed;
    em.max_iterations = options.em_max_iterations;
    em.tolerance = options.em_tolerance;
    em.on_iteration = [&](int iteration, double) {
      if (options.progress) options.progress("pca", static_cast<std::size_t>(iteration), static_cast<std::size_t>(em.max_iterations));
    };
    basis = em_pca(stream, em);
  }
  summary.seconds_pca = since(pca_start);
  summary.explained_fraction = basis.explained_fraction();
  summary.pca_iterations = basis.iterations;
  summary.pca_converged = basis.converged;

  // Every frame's coefficients: c = C^T (b + W^T phi - mean) = (W C)^T phi + C^T (b - mean), phi
  // the map's responses and the contact amount, W their weights (Retargeting).
  const Eigen::MatrixXd projection = retarget.weights() * basis.components;             // m (+1) x k
  const Eigen::VectorXd constant = basis.components.transpose() * (map.offset() - basis.mean);  // k
  const RowMajorMatrixXf coefficients =
      ((responses.transpose() * projection).rowwise() + constant.transpose()).cast<float>();
  if (options.progress) options.progress("coefficients", 1, 1);

  // The feature points on the target face and the rigid markers of the source head frame.
  std::vector<VoiceFeaturePoint> points;
  std::vector<VoiceRigidMarker> rigid;
  const auto sites = marker_sites();
  const auto neutral_m = [&](std::int32_t v) { return Eigen::Vector3d(face.neutral_cm.col(v).cast<double>() / 100.0); };
  for (std::size_t r : source_marker_rows())
    points.push_back({std::string(sites[r].label), sites[r].vertex, neutral_m(sites[r].vertex)});
  const auto rigid_rows = rigid_marker_rows();
  for (std::size_t i = 0; i < rigid_rows.size(); ++i) {
    const MarkerSite& site = sites[rigid_rows[i]];
    rigid.push_back({std::string(site.label), site.vertex, neutral_m(site.vertex),
                     corpus.rigid_reference_cm.col(static_cast<Eigen::Index>(i)) / 100.0});
  }

  summary.utterances = corpus.graph.utterances.size();
  summary.states = corpus.graph.states.size();
  summary.frames = frames;
  summary.prototypes = prototypes.size();
  summary.r_squared_m2 = r_squared;
  summary.lambda = choice.lambda;
  summary.gcv = choice.gcv;
  summary.lambda_at_range_edge = choice.at_range_edge;

  VoiceProvenance provenance;
  provenance.corpus = options.corpus_name.empty() ? corpus_dir.string() : options.corpus_name;
  provenance.target_face = std::string(kDefaultTargetFace);
  provenance.seed = options.seed;
  provenance.synthetic = corpus.synthetic;
  provenance.build_time_utc = options.build_time_utc;
  provenance.tool_version = options.tool_version;
  provenance.parameters = {{"k", k},
                           {"lambda", choice.lambda},
                           {"gcv", choice.gcv},
                           {"lambda_at_range_edge", choice.at_range_edge ? 1 : 0},
                           {"r_squared_m2", r_squared},
                           {"frames", static_cast<double>(frames)},
                           {"utterances", static_cast<double>(summary.utterances)},
                           {"states", static_cast<double>(summary.states)},
                           {"prototypes", static_cast<double>(m)},
                           {"target_prototype_rank", static_cast<double>(summary.target_rank)},
                           {"explained_fraction", summary.explained_fraction},
                           {"pca_iterations", basis.iterations},
                           {"pca_converged", basis.converged ? 1 : 0},
                           {"frames_per_second", kVoiceFramesPerSecond}};
  if (listing.seed) provenance.parameters["corpus_seed"] = static_cast<double>(*listing.seed);
  provenance.notes = {{"prototype_rule", std::string(kSourcePrototypeRule)},
                      {"target_prototypes", std::string(kTargetPrototypeRule)},
                      {"pca_route", std::string(pca_route_name(options.pca))},
                      {"source_vector", "the 34 feature points of spec/markers.tsv, metres, head frame (FPNT order)"}};
  if (contact) provenance.notes["lip_contact"] = std::string(kLipContactRule);
  if (!listing.label.empty()) provenance.notes["corpus_label"] = listing.label;

  VoiceFileWriter writer;
  namespace vs = voice_section;
  writer.add_provenance(provenance);
  writer.add_matrix(vs::kPcaMean, row_f(basis.mean));
  writer.add_matrix(vs::kPcaComponents, RowMajorMatrixXf(basis.components.transpose().cast<float>()));
  writer.add_matrix(vs::kPcaVariances, row_f(basis.variances));
  writer.add_matrix(vs::kFrameCoefficients, coefficients);
  writer.add_matrix(vs::kRbfCentres, RowMajorMatrixXd(map.centres()));
  writer.add_matrix(vs::kRbfWeights, RowMajorMatrixXf(map.weights().cast<float>()));
  writer.add_matrix(vs::kRbfOffset, row_f(map.offset()));
  RowMajorMatrixXd scalars(1, 2);
  scalars << r_squared, choice.lambda;
  writer.add_matrix(vs::kRbfScalars, scalars);
  if (contact) {
    writer.add_matrix(vs::kLipContactShape, row_f(contact->shape));
    RowMajorMatrixXd term(1, static_cast<Eigen::Index>(vs::kLipContactScalars) + m);
    term(0, 0) = contact->gap_offset_m, term(0, 1) = contact->shape_gap_m, term(0, 2) = contact->source_contact_m;
    term(0, 3) = contact->target_contact_m, term(0, 4) = contact->reach_m;
    term.row(0).tail(m) = contact->gap_weights.transpose();
    writer.add_matrix(vs::kLipContact, term);
  }
  const std::vector<std::byte> graph = encode_voice_graph(corpus.graph);
  writer.add(vs::kPhoneGraph, ElementType::kBytes, 1, graph.size(), graph);
  const std::string fpnt = voice_feature_points_json(points, rigid);
  writer.add(vs::kFeaturePoints, ElementType::kJson, 1, fpnt.size(), std::as_bytes(std::span(fpnt)));
  out.bytes = writer.bytes();
  if (options.progress) options.progress("write", 1, 1);
  summary.seconds_total = since(start);
  return out;
}

}  // namespace fapcast
