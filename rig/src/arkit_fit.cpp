#include "fapcast/rig/arkit_fit.hpp"

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include "fapcast/face/face_model.hpp"
#include "fapcast/voice/voice.hpp"

namespace fapcast {

std::optional<std::size_t> arkit_index(std::string_view name) {
  for (std::size_t i = 0; i < kArkitShapes.size(); ++i)
    if (kArkitShapes[i].name == name) return i;
  return std::nullopt;
}

std::string live_link_name(std::string_view arkit_name) {
  std::string s(arkit_name);
  if (!s.empty() && s[0] >= 'a' && s[0] <= 'z') s[0] = static_cast<char>(s[0] - 'a' + 'A');
  return s;
}

namespace {

bool is_lip_point(const std::string& label) {
  return (label.size() == 3 && (label.rfind("2.", 0) == 0 || label.rfind("8.", 0) == 0) && label != "2.1");
}
bool is_jaw_point(const std::string& label) {
  return label == "2.1" || label == "2.10" || label == "2.11" || label == "2.12" || label == "2.13" ||
         label == "2.14";
}


}  // namespace

ArkitFit::ArkitFit(const FaceModel& ict, const Voice& voice, const ArkitFitOptions& options)
    : tongue_out_at_mw_(options.tongue_out_at_mw) {
  const std::int64_t n_vertices = ict.vertex_count();
  if (voice.dimension() != 3 * n_vertices)
    throw std::invalid_argument("ArkitFit: the voice's face has " + std::to_string(voice.dimension() / 3) +
                                " vertices, the ICT face " + std::to_string(n_vertices));
  const auto maps = voice.face_maps();
  for (std::size_t i = 0; i < kArkitShapes.size(); ++i)
    if (kArkitShapes[i].group == ArkitGroup::kMouth) columns_.push_back(static_cast<int>(i));
  const int n = static_cast<int>(columns_.size());
  // Per vertex, the columns that move it and by how much (metres, on the voice's face).
  struct Entry { int column; Eigen::Vector3d offset; };
  std::vector<std::vector<Entry>> at(static_cast<std::size_t>(n_vertices));
  for (int c = 0; c < n; ++c) {
    for (std::string_view ict_name : kArkitShapes[static_cast<std::size_t>(columns_[static_cast<std::size_t>(c)])].ict) {
      if (ict_name.empty()) continue;
      const SparseDelta& d = ict.expressions[ict.expression_index(ict_name)];
      for (std::size_t j = 0; j < d.vertices.size(); ++j) {
        const auto v = static_cast<std::size_t>(d.vertices[j]);
        Eigen::Vector3d off = d.offsets_cm.col(static_cast<Eigen::Index>(j)).cast<double>() * 0.01;
        if (maps) {
          Eigen::Matrix3d a;
          for (int r = 0; r < 3; ++r)
            for (int q = 0; q < 3; ++q) a(r, q) = (*maps)(static_cast<Eigen::Index>(v), 3 * r + q);
          off = a * off;
        }
        auto& list = at[v];
        if (!list.empty() && list.back().column == c) list.back().offset += off;  // a split shape's halves
        else list.push_back({c, off});
      }
    }
  }
  const int k = voice.component_count();
  const auto mean = voice.pca_mean();
  const auto components = voice.pca_components();
  // Products over the region: H = B'B, G = B' PC, g0 = B' (mean - neutral). The neutral of the
  // voice's face is ICT's own for a voice on ICT; a re-targeted voice knows it only at the feature
  // points, so there the mean's offset is fitted on them (below).
  gram_ = Eigen::MatrixXd::Zero(n, n);
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(n, k);
  Eigen::VectorXd g0 = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd pc(k);
  for (std::size_t v = 0; v < at.size(); ++v) {
    const auto& list = at[v];
    if (std::none_of(list.begin(), list.end(), [&](const Entry& e) { return e.offset.norm() > options.region_motion_m; }))
      continue;
    ++region_vertices_;
    for (std::size_t i = 0; i < list.size(); ++i)
      for (std::size_t j = i; j < list.size(); ++j) {
        const double dot = list[i].offset.dot(list[j].offset);
        gram_(list[i].column, list[j].column) += dot;
        if (j != i) gram_(list[j].column, list[i].column) += dot;
      }
    for (int a = 0; a < 3; ++a) {
      const Eigen::Index col = 3 * static_cast<Eigen::Index>(v) + a;
      pc = components.col(col).cast<double>();
      const double offset = maps ? 0.0 : mean(0, col) - 0.01 * ict.neutral_cm(a, static_cast<Eigen::Index>(v));
      for (const Entry& e : list) {
        g.row(e.column) += e.offset[a] * pc.transpose();
        g0[e.column] += e.offset[a] * offset;
      }
    }
  }
  // Feature-point rows.
  const auto fps = voice.feature_points();
  const Eigen::Index rows = 3 * static_cast<Eigen::Index>(fps.size());
  fp_basis_ = Eigen::MatrixXd::Zero(rows, n);
  fp_components_ = Eigen::MatrixXd::Zero(rows, k);
  fp_offset_ = Eigen::VectorXd::Zero(rows);
  for (std::size_t p = 0; p < fps.size(); ++p) {
    const auto v = static_cast<std::size_t>(fps[p].vertex);
    fp_is_lip_.push_back(is_lip_point(fps[p].label));
    fp_is_jaw_.push_back(is_jaw_point(fps[p].label));
    for (const Entry& e : at[v]) fp_basis_.block(3 * static_cast<Eigen::Index>(p), e.column, 3, 1) = e.offset;
    for (int a = 0; a < 3; ++a) {
      const Eigen::Index col = 3 * static_cast<Eigen::Index>(v) + a;
      fp_offset_[3 * static_cast<Eigen::Index>(p) + a] = mean(0, col) - fps[p].neutral_m[a];
      for (int j = 0; j < k; ++j) fp_components_(3 * static_cast<Eigen::Index>(p) + a, j) = components(j, col);
    }
  }
  qp_.emplace(gram_, Eigen::VectorXd::Zero(n), Eigen::VectorXd::Ones(n));
  const Eigen::MatrixXd& h_inverse = qp_->inverse();
  u_of_c_ = h_inverse * g;
  if (maps) {
    // The mean's offset from the (unknown) neutral: its unbounded least-squares weights on the
    // feature points, which the voice's FPNT places on the neutral face exactly.
    u0_ = fp_basis_.colPivHouseholderQr().solve(fp_offset_);  // H^-1 (H w0) = w0
  } else {
    u0_ = h_inverse * g0;
  }
}

Eigen::Vector3d ArkitFit::point_displacement(std::size_t p, const Eigen::VectorXd& w) const {
  return fp_basis_.middleRows(3 * static_cast<Eigen::Index>(p), 3) * w;
}

ArkitTrack ArkitFit::fit(const Eigen::MatrixXf& pca_frames, const Eigen::MatrixXf& tongue) const {
  const Eigen::Index frames = pca_frames.rows();
  const int n = static_cast<int>(columns_.size());
  if (pca_frames.cols() != u_of_c_.cols())
    throw std::invalid_argument("ArkitFit::fit: frames have " + std::to_string(pca_frames.cols()) +
                                " coefficients, the voice " + std::to_string(u_of_c_.cols()));
  if (tongue.size() != 0 && (tongue.rows() != frames || tongue.cols() != 5))
    throw std::invalid_argument("ArkitFit::fit: the tongue track must be frames x 5");
  ArkitTrack track;
  track.weights = Eigen::MatrixXf::Zero(frames, static_cast<Eigen::Index>(kArkitShapeCount));
  track.per_frame.resize(static_cast<std::size_t>(frames));
  BoxQp::WarmStart warm;
  Eigen::VectorXd c(u_of_c_.cols()), u(n), target, error;
  double lip_sum = 0, jaw_sum = 0;
  std::int64_t lip_count = 0, jaw_count = 0;
  static const int tongue_out = static_cast<int>(*arkit_index("tongueOut"));
  for (Eigen::Index f = 0; f < frames; ++f) {
    c = pca_frames.row(f).transpose().cast<double>();
    u.noalias() = u0_ + u_of_c_ * c;
    const Eigen::VectorXd& w = qp_->solve_from_unconstrained(u, warm, &track.solver);
    for (int j = 0; j < n; ++j) track.weights(f, columns_[static_cast<std::size_t>(j)]) = static_cast<float>(w[j]);
    if (tongue.size() != 0) {
      const double out = tongue(f, 2) / (tongue_out_at_mw_ * 1024.0);  // FAP 45 in MW/1024
      track.weights(f, tongue_out) = static_cast<float>(std::clamp(out, 0.0, 1.0));
    }
    target.noalias() = fp_offset_ + fp_components_ * c;
    error.noalias() = fp_basis_ * w - target;
    ArkitResidual& r = track.per_frame[static_cast<std::size_t>(f)];
    double lip = 0, jaw = 0;
    int nl = 0, nj = 0;
    for (std::size_t p = 0; p < fp_is_lip_.size(); ++p) {
      const double e2 = error.segment<3>(3 * static_cast<Eigen::Index>(p)).squaredNorm();
      if (fp_is_lip_[p]) { lip += e2; ++nl; r.lips_max_m = std::max(r.lips_max_m, std::sqrt(e2)); }
      if (fp_is_jaw_[p]) { jaw += e2; ++nj; r.jaw_max_m = std::max(r.jaw_max_m, std::sqrt(e2)); }
    }
    r.lips_rms_m = nl ? std::sqrt(lip / nl) : 0.0;
    r.jaw_rms_m = nj ? std::sqrt(jaw / nj) : 0.0;
    lip_sum += lip; jaw_sum += jaw; lip_count += nl; jaw_count += nj;
    track.residual.lips_max_m = std::max(track.residual.lips_max_m, r.lips_max_m);
    track.residual.jaw_max_m = std::max(track.residual.jaw_max_m, r.jaw_max_m);
  }
  track.residual.lips_rms_m = lip_count ? std::sqrt(lip_sum / static_cast<double>(lip_count)) : 0.0;
  track.residual.jaw_rms_m = jaw_count ? std::sqrt(jaw_sum / static_cast<double>(jaw_count)) : 0.0;
  return track;
}

}  // namespace fapcast
