#include "fapcast/rig/mouth_visemes.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <stdexcept>
#include <string>

#include "fapcast/rig/arkit_fit.hpp"
#include "fapcast/voice/voice.hpp"

namespace fapcast {

std::optional<OculusViseme> oculus_viseme(Phone phone) {
  using V = OculusViseme;
  switch (phone) {
    case Phone::P: case Phone::B: case Phone::M: return V::kPP;
    case Phone::F: case Phone::V: return V::kFF;
    case Phone::TH: case Phone::DH: return V::kTH;
    case Phone::T: case Phone::D: return V::kDD;
    case Phone::K: case Phone::G: case Phone::NG: return V::kKK;
    case Phone::CH: case Phone::JH: case Phone::SH: case Phone::ZH: return V::kCH;
    case Phone::S: case Phone::Z: return V::kSS;
    case Phone::N: case Phone::L: return V::kNN;
    case Phone::R: case Phone::ER: return V::kRR;
    case Phone::AA: case Phone::AH: case Phone::AE: case Phone::AY: case Phone::AW: return V::kAA;
    case Phone::EH: case Phone::EY: case Phone::AX: return V::kE;  // schwa: mid, as e
    case Phone::IH: case Phone::IY: case Phone::Y: return V::kIH;
    case Phone::AO: case Phone::OW: case Phone::OY: return V::kOH;
    case Phone::UH: case Phone::UW: case Phone::W: return V::kOU;
    case Phone::HH: return std::nullopt;
    case Phone::SIL: return V::kSil;
  }
  return V::kSil;
}

std::vector<OculusViseme> oculus_viseme_timeline(std::span<const Phone> phone_per_frame) {
  std::vector<OculusViseme> out(phone_per_frame.size(), OculusViseme::kSil);
  OculusViseme next = OculusViseme::kSil;
  for (std::size_t i = phone_per_frame.size(); i-- > 0;) {
    const auto v = oculus_viseme(phone_per_frame[i]);
    if (v) next = *v;
    out[i] = next;
  }
  return out;
}

namespace {

// min 1/2 w'Qw - c'w over w >= 0, sum w = 1, w_i = 0 where !allowed[i]; primal active set from the
// vertex e_start (feasible), the equality kept in every KKT system. Exact at convergence.
void simplex_qp(const Eigen::MatrixXd& Q, const Eigen::VectorXd& c, const std::array<bool, kOculusVisemeCount>& allowed,
                int start, Eigen::VectorXd& w) {
  constexpr int n = static_cast<int>(kOculusVisemeCount);
  std::array<bool, kOculusVisemeCount> free_{};
  w.setZero(n);
  w[start] = 1;
  free_[static_cast<std::size_t>(start)] = true;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, n + 1, n + 1> kkt;
  Eigen::Matrix<double, Eigen::Dynamic, 1, 0, n + 1, 1> rhs, sol;
  int index[n];
  for (int iteration = 0; iteration < 4 * n + 8; ++iteration) {
    int m = 0;
    for (int i = 0; i < n; ++i)
      if (free_[static_cast<std::size_t>(i)]) index[m++] = i;
    kkt.setZero(m + 1, m + 1);
    rhs.resize(m + 1);
    for (int a = 0; a < m; ++a) {
      for (int b = 0; b < m; ++b) kkt(a, b) = Q(index[a], index[b]);
      kkt(a, m) = kkt(m, a) = 1.0;
      rhs[a] = c[index[a]];
    }
    rhs[m] = 1.0;
    sol = kkt.fullPivLu().solve(rhs);
    double step = 1.0;
    int blocking = -1;
    for (int a = 0; a < m; ++a) {
      const double d = sol[a] - w[index[a]];
      if (sol[a] < 0 && d < 0) {
        const double s = -w[index[a]] / d;
        if (s < step) { step = s; blocking = index[a]; }
      }
    }
    for (int a = 0; a < m; ++a) w[index[a]] += step * (sol[a] - w[index[a]]);
    if (blocking >= 0) {
      w[blocking] = 0;
      free_[static_cast<std::size_t>(blocking)] = false;
      continue;
    }
    // Q w - c + nu 1 = mu, mu_i >= 0 at the zero bound
    const double nu = sol[m];
    int worst = -1;
    double worst_violation = 1e-12 * (1.0 + c.cwiseAbs().maxCoeff());
    for (int i = 0; i < n; ++i) {
      if (free_[static_cast<std::size_t>(i)] || !allowed[static_cast<std::size_t>(i)]) continue;
      const double mu = Q.row(i).dot(w) - c[i] + nu;
      if (-mu > worst_violation) { worst_violation = -mu; worst = i; }
    }
    if (worst < 0) return;
    free_[static_cast<std::size_t>(worst)] = true;
  }
  throw std::logic_error("simplex_qp: the active-set loop did not converge (this is a bug)");
}

}  // namespace

MouthVisemes::MouthVisemes(const ArkitFit& fit, const Voice& voice, const VisemeOptions& options)
    : columns_(fit.columns()), options_(options) {
  const int n = static_cast<int>(columns_.size());
  // Prototypes: fit every corpus phone state's centre frame.
  const auto& states = voice.graph().states();
  const auto phones = voice.state_phones();
  const auto coefficients = voice.frame_coefficients();
  Eigen::MatrixXf centres(static_cast<Eigen::Index>(states.size()), coefficients.cols());
  for (std::size_t s = 0; s < states.size(); ++s)
    centres.row(static_cast<Eigen::Index>(s)) = coefficients.row(states[s].frames.first + states[s].frames.count / 2);
  const ArkitTrack fitted = fit.fit(centres, Eigen::MatrixXf());
  prototypes_ = Eigen::MatrixXd::Zero(n, static_cast<Eigen::Index>(kOculusVisemeCount));
  for (std::size_t s = 0; s < states.size(); ++s) {
    const auto v = oculus_viseme(phones[s]);
    if (!v) continue;
    const auto col = static_cast<std::size_t>(*v);
    for (int j = 0; j < n; ++j) prototypes_(j, static_cast<Eigen::Index>(col)) += fitted.weights(static_cast<Eigen::Index>(s), columns_[static_cast<std::size_t>(j)]);
    ++counts_[col];
  }
  for (std::size_t v = 0; v < kOculusVisemeCount; ++v)
    if (counts_[v] > 0) prototypes_.col(static_cast<Eigen::Index>(v)) /= counts_[v];
  // Metric: H plus the weighted inner-lip opening.
  Eigen::RowVectorXd gap = Eigen::RowVectorXd::Zero(n);
  std::optional<std::size_t> upper, lower;
  const auto fps = voice.feature_points();
  for (std::size_t p = 0; p < fps.size(); ++p) {
    if (fps[p].label == "2.2") upper = p;
    if (fps[p].label == "2.3") lower = p;
  }
  if (upper && lower)
    for (int j = 0; j < n; ++j) {
      Eigen::VectorXd e = Eigen::VectorXd::Zero(n);
      e[j] = 1;
      gap[j] = (fit.point_displacement(*upper, e) - fit.point_displacement(*lower, e)).y();
    }
  metric_ = fit.gram();
  if (gap.squaredNorm() > 0) metric_ += options.gap_weight * metric_.trace() / gap.squaredNorm() * gap.transpose() * gap;
  oculus_pm_ = prototypes_.transpose() * metric_;
  oculus_q_ = oculus_pm_ * prototypes_;
  oculus_scale_ = oculus_q_.trace() / static_cast<double>(kOculusVisemeCount);
  Eigen::MatrixXd vowels(n, static_cast<Eigen::Index>(kVrmVowelCount));
  for (std::size_t j = 0; j < kVrmVowelCount; ++j)
    vowels.col(static_cast<Eigen::Index>(j)) = prototypes_.col(static_cast<Eigen::Index>(kVrmVowelViseme[j]));
  vrm_pm_ = vowels.transpose() * metric_;
  vrm_q_ = vrm_pm_ * vowels;
}

Eigen::MatrixXf MouthVisemes::oculus(const Eigen::MatrixXf& arkit, std::span<const Phone> phone_per_frame) const {
  if (static_cast<std::size_t>(arkit.rows()) != phone_per_frame.size())
    throw std::invalid_argument("MouthVisemes::oculus: " + std::to_string(arkit.rows()) + " frames but " +
                                std::to_string(phone_per_frame.size()) + " phones");
  const auto shown = oculus_viseme_timeline(phone_per_frame);
  const Eigen::Index frames = arkit.rows();
  const int n = static_cast<int>(columns_.size());
  Eigen::MatrixXf out(frames, static_cast<Eigen::Index>(kOculusVisemeCount));
  const Eigen::MatrixXd q = oculus_q_ + options_.prior * oculus_scale_ *
                                            Eigen::MatrixXd::Identity(kOculusVisemeCount, kOculusVisemeCount);
  Eigen::VectorXd a(n), c, w;
  for (Eigen::Index f = 0; f < frames; ++f) {
    for (int j = 0; j < n; ++j) a[j] = arkit(f, columns_[static_cast<std::size_t>(j)]);
    const int own = static_cast<int>(shown[static_cast<std::size_t>(f)]);
    std::array<bool, kOculusVisemeCount> allowed{};
    allowed[static_cast<std::size_t>(OculusViseme::kSil)] = true;
    const Eigen::Index lo = std::max<Eigen::Index>(0, f - options_.support_frames);
    const Eigen::Index hi = std::min<Eigen::Index>(frames - 1, f + options_.support_frames);
    for (Eigen::Index g = lo; g <= hi; ++g) allowed[static_cast<std::size_t>(shown[static_cast<std::size_t>(g)])] = true;
    c = oculus_pm_ * a;
    c[own] += options_.prior * oculus_scale_;
    simplex_qp(q, c, allowed, own, w);
    out.row(f) = w.transpose().cast<float>();
  }
  return out;
}

Eigen::MatrixXf MouthVisemes::vrm(const Eigen::MatrixXf& arkit) const {
  const Eigen::Index frames = arkit.rows();
  const int n = static_cast<int>(columns_.size());
  BoxQp qp(vrm_q_, Eigen::VectorXd::Zero(kVrmVowelCount), Eigen::VectorXd::Ones(kVrmVowelCount));
  BoxQp::WarmStart warm;
  Eigen::MatrixXf out(frames, static_cast<Eigen::Index>(kVrmVowelCount));
  Eigen::VectorXd a(n), u;
  for (Eigen::Index f = 0; f < frames; ++f) {
    for (int j = 0; j < n; ++j) a[j] = arkit(f, columns_[static_cast<std::size_t>(j)]);
    u = qp.inverse() * (vrm_pm_ * a);
    out.row(f) = qp.solve_from_unconstrained(u, warm).transpose().cast<float>();
  }
  return out;
}

}  // namespace fapcast
