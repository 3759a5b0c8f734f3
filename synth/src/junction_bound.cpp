#include "fapcast/synth/junction_bound.hpp"

#include "fapcast/synth/phone_graph.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>

namespace fapcast::synth {
namespace {

constexpr auto kClasses = static_cast<Eigen::Index>(kVisemeClassCount);

Eigen::Index of(VisemeClass v) { return static_cast<Eigen::Index>(v); }

using Rows = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

}  // namespace

JunctionBound::JunctionBound(const PhoneGraph& graph) {
  const auto& f = graph.junction();
  const auto n = static_cast<Eigen::Index>(graph.size());
  const Eigen::Index dims = f.entry.cols();
  // The float cost sums `dims` squares (relative error below dims eps of 2C <= 2 (E + X), with E
  // and X the two spreads below); the stored floats and the bound's float arithmetic add a few eps
  // of E + X. 32 (dims + 8) eps of each spread is far above both and far below any decision.
  const double slack_per_spread = 32.0 * static_cast<double>(dims + 8) * std::numeric_limits<float>::epsilon();
  auto state_class = [&](Eigen::Index i) { return of(graph.state(static_cast<StateId>(i)).viseme); };

  // c_a: the mean exit row of class a.
  Rows centre = Rows::Zero(kClasses, dims);
  Eigen::VectorXd count = Eigen::VectorXd::Zero(kClasses);
  for (Eigen::Index i = 0; i < n; ++i) {
    centre.row(state_class(i)) += f.exit.row(i).cast<double>();
    count(state_class(i)) += 1.0;
  }
  for (Eigen::Index c = 0; c < kClasses; ++c)
    if (count(c) > 0) centre.row(c) /= count(c);

  // q_ab: from c_a towards the mean entry row of diviseme a b, unit length (zero when the two
  // coincide or the diviseme was never recorded: the bound stays valid, only weaker).
  Rows axis = Rows::Zero(kClasses * kClasses, dims);
  for (Eigen::Index a = 0; a < kClasses; ++a)
    for (Eigen::Index b = 0; b < kClasses; ++b) {
      const auto entries = graph.entries(static_cast<VisemeClass>(a), static_cast<VisemeClass>(b));
      if (entries.empty()) continue;
      Eigen::RowVectorXd towards = -centre.row(a);
      for (StateId j : entries) towards += f.entry.row(j).cast<double>() / static_cast<double>(entries.size());
      const double norm = towards.norm();
      if (norm > 0.0 && std::isfinite(norm)) axis.row(a * kClasses + b) = towards / norm;
    }

  auto on_axis = [](double spread, double along) {
    return OnAxis{static_cast<float>(along), static_cast<float>(std::sqrt(std::max(0.0, spread - along * along)))};
  };
  entry_.assign(static_cast<std::size_t>(n), {});
  for (Eigen::Index j = 0; j < n; ++j) {
    if (!graph.has_parent(static_cast<StateId>(j))) continue;
    const Eigen::Index a = state_class(j - 1);
    const Eigen::RowVectorXd r = f.entry.row(j).cast<double>() - centre.row(a);
    const double spread = r.squaredNorm();
    const OnAxis p = on_axis(spread, r.dot(axis.row(a * kClasses + state_class(j))));
    entry_[static_cast<std::size_t>(j)] = {p.along, p.across, static_cast<float>(slack_per_spread * spread)};
  }
  offset_.assign(kVisemeClassCount * kVisemeClassCount + 1, 0);
  for (std::size_t d = 0; d < kVisemeClassCount * kVisemeClassCount; ++d)
    offset_[d + 1] = offset_[d] + graph.entries(static_cast<VisemeClass>(d / kVisemeClassCount),
                                                static_cast<VisemeClass>(d % kVisemeClassCount)).size();
  entry_by_diviseme_.resize(offset_.back());
  entry_rows_.resize(static_cast<Eigen::Index>(offset_.back()), dims);
  for (std::size_t d = 0; d < kVisemeClassCount * kVisemeClassCount; ++d) {
    const auto entries = graph.entries(static_cast<VisemeClass>(d / kVisemeClassCount),
                                       static_cast<VisemeClass>(d % kVisemeClassCount));
    for (std::size_t m = 0; m < entries.size(); ++m) {
      entry_by_diviseme_[offset_[d] + m] = entry_[entries[m]];
      entry_rows_.row(static_cast<Eigen::Index>(offset_[d] + m)) = f.entry.row(entries[m]);
    }
  }
  // Every exit on every axis of its class: one product per class, (states of a) x (axes of a).
  exit_.resize(static_cast<std::size_t>(n * kClasses));
  exit_slack_.resize(static_cast<std::size_t>(n));
  for (Eigen::Index a = 0; a < kClasses; ++a) {
    const auto members = graph.with_viseme(static_cast<VisemeClass>(a));
    if (members.empty()) continue;
    Rows r(static_cast<Eigen::Index>(members.size()), dims);
    for (std::size_t m = 0; m < members.size(); ++m)
      r.row(static_cast<Eigen::Index>(m)) = f.exit.row(members[m]).cast<double>() - centre.row(a);
    const Eigen::MatrixXd along = r * axis.middleRows(a * kClasses, kClasses).transpose();  // members x classes
    for (std::size_t m = 0; m < members.size(); ++m) {
      const auto row = static_cast<Eigen::Index>(m);
      const double spread = r.row(row).squaredNorm();
      exit_slack_[members[m]] = static_cast<float>(slack_per_spread * spread);
      for (Eigen::Index b = 0; b < kClasses; ++b)
        exit_[static_cast<std::size_t>(members[m]) * kVisemeClassCount + static_cast<std::size_t>(b)] =
            on_axis(spread, along(row, b));
    }
  }
}

}  // namespace fapcast::synth
