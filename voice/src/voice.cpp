#include "fapcast/voice/voice.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <mutex>
#include <set>
#include <sstream>

#include "fapcast/core/input_error.hpp"
#include "fapcast/voice/voice_graph.hpp"

namespace fapcast {
namespace {

namespace vs = voice_section;

[[noreturn]] void refuse(const VoiceFileView& view, SectionId id, const std::string& rule, const std::string& detail) {
  const SectionInfo* s = view.find(id);
  throw InputError({view.source(), std::nullopt, s ? s->offset : 0}, rule,
                   "section '" + id.str() + "' (" + std::string(section_name(id)) + "): " + detail);
}

// The lip-contact term of LCSH and LCON (nullopt without them), refused with lip-contact when its
// values cannot be a contact term or the feature points lack the inner lips' 2.2 and 2.3.
std::optional<LipContact> lip_contact_of(const VoiceFileView& view, std::span<const VoiceFeaturePoint> points) {
  if (view.find(vs::kLipContact) == nullptr) return std::nullopt;
  const auto row = view.matrix_f64(vs::kLipContact);
  LipContact c;
  c.gap_offset_m = row(0, 0), c.shape_gap_m = row(0, 1), c.source_contact_m = row(0, 2);
  c.target_contact_m = row(0, 3), c.reach_m = row(0, 4);
  c.gap_weights = row.row(0).tail(row.cols() - static_cast<Eigen::Index>(vs::kLipContactScalars)).transpose();
  c.shape = view.matrix_f32(vs::kLipContactShape).row(0).transpose().cast<double>();
  const auto bad = [&](const std::string& detail) { refuse(view, vs::kLipContact, "lip-contact", detail); };
  if (!row.allFinite() || !c.shape.allFinite()) bad("a value of the term or of its shape is a NaN or an infinity");
  if (!(c.shape_gap_m < 0)) bad("the shape does not close the lips (gap change " + std::to_string(c.shape_gap_m) + " m per unit, must be negative)");
  if (!(c.reach_m > 0) || !(c.source_contact_m >= 0))
    bad("the reach (" + std::to_string(c.reach_m) + " m) must be positive and the source contact (" +
        std::to_string(c.source_contact_m) + " m) not negative");
  c.source_upper = c.source_lower = -1;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (points[i].label == "2.2") c.source_upper = 3 * static_cast<Eigen::Index>(i);
    if (points[i].label == "2.3") c.source_lower = 3 * static_cast<Eigen::Index>(i);
  }
  if (c.source_upper < 0 || c.source_lower < 0) bad("the feature points lack the inner lips' 2.2 or 2.3");
  return c;
}

nlohmann::json vector_json(const Eigen::Vector3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

// Reads FPNT: {"feature_points": [{label, vertex, neutral_m}], "rigid_markers": [{label, vertex,
// neutral_m, source_reference_m}]}.
void read_feature_points(const VoiceFileView& view, Eigen::Index vertices, Eigen::Index source_dimension,
                         std::vector<VoiceFeaturePoint>& points, std::vector<VoiceRigidMarker>& rigid) {
  const SectionInfo& s = view.require(vs::kFeaturePoints);
  if (s.type != ElementType::kJson)
    refuse(view, vs::kFeaturePoints, "section-type", "element type " + std::to_string(static_cast<unsigned>(s.type)) + ", expected 5 (json)");
  const auto raw = view.bytes(vs::kFeaturePoints);
  const nlohmann::json j = nlohmann::json::parse(std::string_view(reinterpret_cast<const char*>(raw.data()), raw.size()),
                                                 nullptr, /*allow_exceptions=*/false);
  const auto bad = [&](const std::string& detail) { refuse(view, vs::kFeaturePoints, "feature-points", detail); };
  if (j.is_discarded() || !j.is_object()) bad("not a JSON object");
  std::set<std::string> labels;
  const auto read3 = [&](const nlohmann::json& e, const std::string& where, const char* key, Eigen::Vector3d& out) {
    const auto a = e.find(key);
    if (a == e.end() || !a->is_array() || a->size() != 3 || !(*a)[0].is_number() || !(*a)[1].is_number() ||
        !(*a)[2].is_number())
      bad(where + ": \"" + key + "\" must be 3 numbers");
    out = {(*a)[0].get<double>(), (*a)[1].get<double>(), (*a)[2].get<double>()};
  };
  const auto point = [&](const nlohmann::json& e, const std::string& where, std::string& label, std::int32_t& vertex,
                         Eigen::Vector3d& neutral) {
    if (!e.is_object()) bad(where + " is not an object");
    const auto l = e.find("label");
    if (l == e.end() || !l->is_string() || l->get<std::string>().empty()) bad(where + ": \"label\" must be a non-empty string");
    label = l->get<std::string>();
    if (!labels.insert(label).second) bad(where + ": label \"" + label + "\" repeats");
    const auto v = e.find("vertex");
    if (v == e.end() || !v->is_number_integer() || v->get<std::int64_t>() < 0 || v->get<std::int64_t>() >= vertices)
      bad(where + " (" + label + "): \"vertex\" must be an integer in [0, " + std::to_string(vertices) + ")");
    vertex = static_cast<std::int32_t>(v->get<std::int64_t>());
    read3(e, where, "neutral_m", neutral);
  };
  const auto fps = j.find("feature_points");
  if (fps == j.end() || !fps->is_array()) bad("\"feature_points\" must be an array");
  for (std::size_t i = 0; i < fps->size(); ++i) {
    VoiceFeaturePoint p{};
    point((*fps)[i], "feature_points[" + std::to_string(i) + "]", p.label, p.vertex, p.neutral_m);
    points.push_back(std::move(p));
  }
  if (3 * static_cast<Eigen::Index>(points.size()) != source_dimension)
    bad(std::to_string(points.size()) + " feature points, but the RBF centres have " + std::to_string(source_dimension) +
        " source coordinates (3 per point)");
  const auto rms = j.find("rigid_markers");
  if (rms == j.end() || !rms->is_array()) bad("\"rigid_markers\" must be an array");
  for (std::size_t i = 0; i < rms->size(); ++i) {
    VoiceRigidMarker r{};
    const std::string where = "rigid_markers[" + std::to_string(i) + "]";
    point((*rms)[i], where, r.label, r.vertex, r.neutral_m);
    read3((*rms)[i], where, "source_reference_m", r.source_reference_m);
    rigid.push_back(std::move(r));
  }
  if (rigid.size() < 3) bad(std::to_string(rigid.size()) + " rigid markers, head-pose removal needs at least 3");
}

}  // namespace

std::string voice_feature_points_json(std::span<const VoiceFeaturePoint> feature_points,
                                      std::span<const VoiceRigidMarker> rigid_markers) {
  nlohmann::ordered_json j;
  j["feature_points"] = nlohmann::ordered_json::array();
  for (const auto& p : feature_points)
    j["feature_points"].push_back({{"label", p.label}, {"vertex", p.vertex}, {"neutral_m", vector_json(p.neutral_m)}});
  j["rigid_markers"] = nlohmann::ordered_json::array();
  for (const auto& r : rigid_markers)
    j["rigid_markers"].push_back({{"label", r.label},
                                  {"vertex", r.vertex},
                                  {"neutral_m", vector_json(r.neutral_m)},
                                  {"source_reference_m", vector_json(r.source_reference_m)}});
  return j.dump(1) + "\n";
}

Voice::Voice(VoiceFileView view, VoiceProvenance provenance, std::vector<VoiceFeaturePoint> feature_points,
             std::vector<VoiceRigidMarker> rigid_markers, PhoneGraph graph,
             std::vector<Phone> phones, std::vector<FrameSpan> utterances, double rbf_r_squared, double rbf_lambda)
    : view_(std::move(view)),
      provenance_(std::move(provenance)),
      feature_points_(std::move(feature_points)),
      rigid_markers_(std::move(rigid_markers)),
      graph_(std::move(graph)),
      phones_(std::move(phones)),
      utterances_(std::move(utterances)),
      rbf_r_squared_(rbf_r_squared),
      rbf_lambda_(rbf_lambda),
      map_(std::make_unique<RetargetMapOnce>()) {
  components_rows_ = static_cast<Eigen::Index>(view_.require(vs::kPcaComponents).rows);
  dimension_ = static_cast<Eigen::Index>(view_.require(vs::kPcaMean).cols);
}

struct Voice::RetargetMapOnce {
  std::once_flag once;
  std::optional<RbfMap> map;
  std::optional<Retargeting> retargeting;
};

const RbfMap& Voice::retarget_map() const { return retargeting().map(); }

const Retargeting& Voice::retargeting() const {
  // The sections' shapes (m x D weights, 1 x D offset, LCSH and LCON) and the contact's values
  // were checked at open: this cannot throw.
  std::call_once(map_->once, [this] {
    map_->map.emplace(Eigen::MatrixXd(view_.matrix_f64(vs::kRbfCentres)), rbf_r_squared_,
                      view_.matrix_f32(vs::kRbfWeights).cast<double>(),
                      view_.matrix_f32(vs::kRbfOffset).row(0).transpose().cast<double>(), rbf_lambda_);
    map_->retargeting.emplace(*map_->map, lip_contact_of(view_, feature_points_));
  });
  return *map_->retargeting;
}

Voice::Voice(Voice&&) noexcept = default;
Voice& Voice::operator=(Voice&&) noexcept = default;
Voice::~Voice() = default;

Voice Voice::open(const std::filesystem::path& path) { return from_view(VoiceFileView::open(path)); }

Voice Voice::over_bytes(std::span<const std::byte> bytes, std::string source) {
  return from_view(VoiceFileView::over_bytes(bytes, std::move(source)));
}

Voice Voice::from_view(VoiceFileView view) {
  check_voice_sections(view);  // open_voice's checks, the provenance parsed once (here)
  VoiceProvenance provenance = view.provenance();
  const Eigen::Index d = static_cast<Eigen::Index>(view.require(vs::kPcaMean).cols);
  if (d % 3 != 0) refuse(view, vs::kPcaMean, "section-shape", "D = " + std::to_string(d) + " is not 3 x vertices");
  const auto centres = view.matrix_f64(vs::kRbfCentres);
  std::vector<VoiceFeaturePoint> points;
  std::vector<VoiceRigidMarker> rigid;
  read_feature_points(view, d / 3, centres.cols(), points, rigid);

  const SectionInfo& grph = view.require(vs::kPhoneGraph);
  VoiceGraphData graph = decode_voice_graph(view.bytes(vs::kPhoneGraph), view.source(), grph.offset);
  const auto coefficients = view.matrix_f32(vs::kFrameCoefficients);
  if (static_cast<Eigen::Index>(graph.frame_count) != coefficients.rows())
    refuse(view, vs::kPhoneGraph, "section-shape", "the graph covers " + std::to_string(graph.frame_count) +
                                                       " frames, FCOE has " + std::to_string(coefficients.rows()));
  const auto scalars = view.matrix_f64(vs::kRbfScalars);
  const double r_squared = scalars(0, 0), lambda = scalars(0, 1);
  if (!(r_squared > 0) || !std::isfinite(r_squared) || !(lambda >= 0) || !std::isfinite(lambda)) {
    std::ostringstream detail;
    detail << "r^2 = " << r_squared << " must be positive and lambda = " << lambda << " non-negative, both finite";
    refuse(view, vs::kRbfScalars, "rbf-scalars", detail.str());
  }
  if (const SectionInfo* maps = view.find(vs::kFaceMaps)) {
    if (maps->type != ElementType::kFloat32 || maps->rows != static_cast<std::uint64_t>(d / 3) || maps->cols != 9)
      refuse(view, vs::kFaceMaps, "section-shape",
             "expected float32 " + std::to_string(d / 3) + " x 9 (one 3 x 3 map per vertex), found type " +
                 std::to_string(static_cast<unsigned>(maps->type)) + ", " + std::to_string(maps->rows) + " x " +
                 std::to_string(maps->cols));
    if (!view.matrix_f32(vs::kFaceMaps).allFinite())
      refuse(view, vs::kFaceMaps, "non-finite", "a face map holds a NaN or an infinity");
  }
  (void)lip_contact_of(view, points);  // refused here, not on first use
  JoinFeatures join = join_features(graph.states, coefficients);
  PhoneGraph phone_graph(std::move(graph.states), std::move(join));
  return Voice(std::move(view), std::move(provenance), std::move(points), std::move(rigid),
               std::move(phone_graph), std::move(graph.phones), std::move(graph.utterances), r_squared, lambda);
}

Eigen::Map<const RowMajorMatrixXf> Voice::frame_coefficients() const {
  return view_.matrix_f32(vs::kFrameCoefficients);
}
Eigen::Map<const RowMajorMatrixXf> Voice::pca_mean() const { return view_.matrix_f32(vs::kPcaMean); }
Eigen::Map<const RowMajorMatrixXf> Voice::pca_components() const { return view_.matrix_f32(vs::kPcaComponents); }
Eigen::Map<const RowMajorMatrixXf> Voice::pca_variances() const { return view_.matrix_f32(vs::kPcaVariances); }
std::optional<Eigen::Map<const RowMajorMatrixXf>> Voice::face_maps() const {
  if (view_.find(vs::kFaceMaps) == nullptr) return std::nullopt;
  return view_.matrix_f32(vs::kFaceMaps);
}

}  // namespace fapcast
