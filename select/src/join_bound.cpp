#include "fapcast/select/join_bound.hpp"

#include "fapcast/select/phone_graph.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>

namespace fapcast {
namespace {

constexpr auto kClasses = static_cast<Eigen::Index>(kVisemeClassCount);

Eigen::Index of(VisemeClass v) { return static_cast<Eigen::Index>(v); }

}  // namespace

struct JoinBound::Lazy {
  std::once_flag once;
  DivisemePoints points;
  std::atomic<std::size_t> computed{0};  // exit points computed per call so far
  std::atomic<bool> tabled{false};
  std::once_flag table_once;
  std::vector<JoinPoint> exit;       // every state of class `from`, in with_viseme order
  std::atomic<std::size_t> sketch_calls{0};
  std::once_flag sketch_once;
  DivisemeSketches sketches;
};

struct JoinBound::ClassSketches {
  std::atomic<std::size_t> computed{0};  // sketches made per call so far
  std::atomic<bool> tabled{false};
  std::once_flag once;
  std::vector<std::int16_t> rows;  // every exit of the class, in with_viseme order
  std::vector<float> error;
};

namespace {

// A row relative to c_a on the unit axis q: along = (row - c_a) . q, across = |r - along q|.
JoinPoint point_on_axis(const float* row, const Eigen::Ref<const Eigen::RowVectorXd>& centre,
                            const Eigen::Ref<const Eigen::RowVectorXd>& axis, double slack_per_spread) {
  const auto r = Eigen::Map<const Eigen::RowVectorXf>(row, centre.size()).cast<double>() - centre;  // no allocation
  const double spread = r.squaredNorm(), along = r.dot(axis);
  return {static_cast<float>(along), static_cast<float>(std::sqrt(std::max(0.0, spread - along * along))),
          static_cast<float>(slack_per_spread * spread)};
}

}  // namespace

JoinBound::Shared::~Shared() = default;

JoinBound::JoinBound(const PhoneGraph& graph) : shared_(std::make_shared<Shared>()) {
  const auto& f = graph.join_features();
  const auto n = static_cast<Eigen::Index>(graph.size());
  const Eigen::Index dims = f.entry.cols();
  Shared& s = *shared_;
  // The float cost sums `dims` squares (relative error below dims eps of 2C <= 2 (E + X), with E
  // and X the two spreads below); the stored floats and the bound's float arithmetic add a few eps
  // of E + X. 32 (dims + 8) eps of each spread is far above both and far below any decision.
  s.slack_per_spread = 32.0 * static_cast<double>(dims + 8) * std::numeric_limits<float>::epsilon();

  // c_a: the mean exit row of class a.
  s.centre = Rows::Zero(kClasses, dims);
  for (Eigen::Index a = 0; a < kClasses; ++a) {
    const auto members = graph.with_viseme(static_cast<VisemeClass>(a));
    for (StateId i : members) s.centre.row(a) += f.exit.row(i).cast<double>();
    if (!members.empty()) s.centre.row(a) /= static_cast<double>(members.size());
  }
  s.rank.resize(static_cast<std::size_t>(n));
  for (Eigen::Index a = 0; a < kClasses; ++a) {
    const auto members = graph.with_viseme(static_cast<VisemeClass>(a));
    for (std::size_t m = 0; m < members.size(); ++m) s.rank[members[m]] = static_cast<std::uint32_t>(m);
  }

  // q_ab: from c_a towards the mean entry row of diviseme a b, unit length (zero when the two
  // coincide or the diviseme was never recorded: the bound stays valid, only weaker).
  s.axis = Rows::Zero(kClasses * kClasses, dims);
  Eigen::RowVectorXd towards(dims);
  for (Eigen::Index a = 0; a < kClasses; ++a)
    for (Eigen::Index b = 0; b < kClasses; ++b) {
      const auto entries = graph.entries(static_cast<VisemeClass>(a), static_cast<VisemeClass>(b));
      if (entries.empty()) continue;
      towards.setZero();
      for (StateId j : entries) towards += f.entry.row(j).cast<double>();
      towards = towards / static_cast<double>(entries.size()) - s.centre.row(a);
      const double norm = towards.norm();
      if (norm > 0.0 && std::isfinite(norm)) s.axis.row(a * kClasses + b) = towards / norm;
    }
  s.divisemes = std::make_unique<Lazy[]>(kVisemeClassCount * kVisemeClassCount);
  s.sketched = dims > 0 && dims <= kSketchMaxDims;
  if (s.sketched) {
    s.grid = fapcast::sketch_grid(f);
    s.sketches = std::make_unique<ClassSketches[]>(kVisemeClassCount);
  }
}

const DivisemePoints& JoinBound::points(const PhoneGraph& graph, VisemeClass from, VisemeClass to) const {
  Lazy& lazy = shared_->divisemes[static_cast<std::size_t>(of(from) * kClasses + of(to))];
  std::call_once(lazy.once, [&] {
    const Shared& s = *shared_;
    const auto& f = graph.join_features();
    const Eigen::Index dims = f.entry.cols();
    const auto centre = s.centre.row(of(from));
    const auto axis = s.axis.row(of(from) * kClasses + of(to));
    DivisemePoints& p = lazy.points;
    const auto entries = graph.entries(from, to);
    p.entry.resize(entries.size());
    p.entry_rows.resize(static_cast<Eigen::Index>(entries.size()), dims);
    for (std::size_t m = 0; m < entries.size(); ++m) {
      p.entry[m] = point_on_axis(f.entry.row(entries[m]).data(), centre, axis, s.slack_per_spread);
      p.entry_rows.row(static_cast<Eigen::Index>(m)) = f.entry.row(entries[m]);
      p.along_mean += p.entry[m].along, p.across_mean += p.entry[m].across;
    }
    if (!entries.empty())
      p.along_mean /= static_cast<double>(entries.size()), p.across_mean /= static_cast<double>(entries.size());
  });
  return lazy.points;
}

void JoinBound::exits(const PhoneGraph& graph, VisemeClass from, VisemeClass to,
                          std::span<const std::uint32_t> states, std::span<JoinPoint> out) const {
  const Shared& s = *shared_;
  Lazy& lazy = s.divisemes[static_cast<std::size_t>(of(from) * kClasses + of(to))];
  const auto& f = graph.join_features();
  const auto centre = s.centre.row(of(from));
  const auto axis = s.axis.row(of(from) * kClasses + of(to));
  const auto members = graph.with_viseme(from);
  if (!lazy.tabled.load(std::memory_order_acquire) &&
      lazy.computed.fetch_add(states.size(), std::memory_order_relaxed) < members.size()) {
    for (std::size_t m = 0; m < states.size(); ++m)
      out[m] = point_on_axis(f.exit.row(states[m]).data(), centre, axis, s.slack_per_spread);
    return;
  }
  std::call_once(lazy.table_once, [&] {
    lazy.exit.resize(members.size());
    for (std::size_t m = 0; m < members.size(); ++m)
      lazy.exit[m] = point_on_axis(f.exit.row(members[m]).data(), centre, axis, s.slack_per_spread);
    lazy.tabled.store(true, std::memory_order_release);
  });
  for (std::size_t m = 0; m < states.size(); ++m) out[m] = lazy.exit[s.rank[states[m]]];
}

const DivisemeSketches* JoinBound::entry_sketches(const PhoneGraph& graph, VisemeClass from, VisemeClass to) const {
  if (!sketched()) return nullptr;
  const Shared& s = *shared_;
  Lazy& lazy = s.divisemes[static_cast<std::size_t>(of(from) * kClasses + of(to))];
  if (lazy.sketch_calls.fetch_add(1, std::memory_order_relaxed) == 0) return nullptr;
  std::call_once(lazy.sketch_once, [&] {
    const auto& f = graph.join_features();
    const auto dims = static_cast<std::size_t>(f.entry.cols());
    const auto entries = graph.entries(from, to);
    DivisemeSketches& k = lazy.sketches;
    k.entry.resize(entries.size() * dims);
    k.error.resize(entries.size());
    for (std::size_t m = 0; m < entries.size(); ++m)
      k.error[m] = sketch_row(f.entry.row(entries[m]).data(), f.entry.cols(), s.grid, k.entry.data() + m * dims);
  });
  return &lazy.sketches;
}

void JoinBound::exit_sketches(const PhoneGraph& graph, VisemeClass from, std::span<const std::uint32_t> states,
                                  std::span<SketchRef> out, std::vector<std::int16_t>& buffer) const {
  const Shared& s = *shared_;
  ClassSketches& table = s.sketches[static_cast<std::size_t>(of(from))];
  const auto& f = graph.join_features();
  const auto dims = static_cast<std::size_t>(f.exit.cols());
  const auto members = graph.with_viseme(from);
  if (!table.tabled.load(std::memory_order_acquire) &&
      table.computed.fetch_add(states.size(), std::memory_order_relaxed) < members.size()) {
    buffer.resize(states.size() * dims);
    for (std::size_t m = 0; m < states.size(); ++m)
      out[m] = {buffer.data() + m * dims, sketch_row(f.exit.row(states[m]).data(), f.exit.cols(), s.grid, buffer.data() + m * dims)};
    return;
  }
  std::call_once(table.once, [&] {
    table.rows.resize(members.size() * dims);
    table.error.resize(members.size());
    for (std::size_t m = 0; m < members.size(); ++m)
      table.error[m] = sketch_row(f.exit.row(members[m]).data(), f.exit.cols(), s.grid, table.rows.data() + m * dims);
    table.tabled.store(true, std::memory_order_release);
  });
  for (std::size_t m = 0; m < states.size(); ++m) {
    const std::uint32_t r = s.rank[states[m]];
    out[m] = {table.rows.data() + r * dims, table.error[r]};
  }
}

}  // namespace fapcast
