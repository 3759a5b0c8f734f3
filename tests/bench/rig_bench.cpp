// The ARKit fit of 60 s of animation (3,600 frames at 60 fps) on a voice's face, against the
// obvious alternatives in the same run: the textbook primal active set that factors H_FF at every
// step, and the unfactored fit that rebuilds each frame's displacement on the region's vertices and
// projects it on the shapes before solving (spec/rigs.md, "Speed").
//   FAPCAST_BENCH_VOICE=V.fapv build/rel/tests/rig_bench
// Frames: the voice's own corpus frames (PCA coefficients of captured speech), the first 3,600.
#include <benchmark/benchmark.h>

#include <Eigen/Cholesky>
#include <cstdlib>
#include <memory>

#include "fapcast/face/face_model.hpp"
#include "fapcast/rig/arkit_fit.hpp"
#include "fapcast/rig/mouth_visemes.hpp"
#include "fapcast/voice/voice.hpp"

namespace fapcast {
namespace {

constexpr Eigen::Index kFrames = 3600;

struct Fixture {
  Voice voice;
  ArkitFit fit;
  Eigen::MatrixXf frames;
  // for the unfactored fit: the fitted shapes and the PCA basis on the region's coordinates
  Eigen::MatrixXd shapes, components;
  Eigen::VectorXd offset;
};

Fixture* fixture() {
  static std::unique_ptr<Fixture> f = [] {
    const char* path = std::getenv("FAPCAST_BENCH_VOICE");
    if (!path) return std::unique_ptr<Fixture>();
    Voice v = Voice::open(path);
    const FaceModel& face = ict_face_model();
    ArkitFit fit(face, v);
    Eigen::MatrixXf frames = v.frame_coefficients().topRows(std::min<Eigen::Index>(kFrames, v.frame_coefficients().rows()));
    // the region: every vertex a fitted shape moves more than 0.1 mm (as ArkitFit), dense
    std::vector<Eigen::Matrix3Xd> dense;
    std::vector<char> in_region(static_cast<std::size_t>(face.vertex_count()), 0);
    for (int c : fit.columns()) {
      Eigen::Matrix3Xd d = Eigen::Matrix3Xd::Zero(3, face.vertex_count());
      for (std::string_view name : kArkitShapes[static_cast<std::size_t>(c)].ict) {
        if (name.empty()) continue;
        const SparseDelta& s = face.expressions[face.expression_index(name)];
        for (std::size_t j = 0; j < s.vertices.size(); ++j)
          d.col(s.vertices[j]) += s.offsets_cm.col(static_cast<Eigen::Index>(j)).cast<double>() * 0.01;
      }
      for (Eigen::Index v2 = 0; v2 < d.cols(); ++v2)
        if (d.col(v2).norm() > 1e-4) in_region[static_cast<std::size_t>(v2)] = 1;
      dense.push_back(std::move(d));
    }
    std::vector<Eigen::Index> region;
    for (std::size_t v2 = 0; v2 < in_region.size(); ++v2)
      if (in_region[v2]) region.push_back(static_cast<Eigen::Index>(v2));
    const Eigen::Index rows = 3 * static_cast<Eigen::Index>(region.size());
    Eigen::MatrixXd shapes(rows, static_cast<Eigen::Index>(dense.size())), components(rows, v.component_count());
    Eigen::VectorXd offset(rows);
    const auto mean = v.pca_mean();
    const auto pc = v.pca_components();
    for (std::size_t r = 0; r < region.size(); ++r)
      for (int a = 0; a < 3; ++a) {
        const Eigen::Index row = 3 * static_cast<Eigen::Index>(r) + a, col = 3 * region[r] + a;
        for (std::size_t c = 0; c < dense.size(); ++c) shapes(row, static_cast<Eigen::Index>(c)) = dense[c](a, region[r]);
        for (int k = 0; k < v.component_count(); ++k) components(row, k) = pc(k, col);
        offset[row] = mean(0, col) - 0.01 * face.neutral_cm(a, region[r]);
      }
    return std::make_unique<Fixture>(Fixture{std::move(v), std::move(fit), std::move(frames), std::move(shapes),
                                             std::move(components), std::move(offset)});
  }();
  return f.get();
}

#define NEED_VOICE(state)                                                     \
  Fixture* fx = fixture();                                                    \
  if (!fx) {                                                                  \
    state.SkipWithError("set FAPCAST_BENCH_VOICE to a voice file (.fapv)");  \
    return;                                                                   \
  }

void BM_ArkitFit_60s(benchmark::State& state) {
  NEED_VOICE(state);
  double iterations = 0;
  for (auto _ : state) {
    ArkitTrack t = fx->fit.fit(fx->frames, Eigen::MatrixXf());
    iterations = static_cast<double>(t.solver.iterations) / static_cast<double>(t.solver.solves);
    benchmark::DoNotOptimize(t.weights.data());
  }
  state.counters["subproblems_per_frame"] = iterations;
  state.counters["frames"] = static_cast<double>(fx->frames.rows());
}

// The textbook primal active set: each step factors the free block H_FF of the Gram matrix.
Eigen::VectorXd primal_refactor(const Eigen::MatrixXd& h, const Eigen::VectorXd& q, Eigen::VectorXd x, std::vector<char>& free_) {
  const int n = static_cast<int>(q.size());
  for (int it = 0; it < 4 * n + 8; ++it) {
    std::vector<int> f;
    for (int i = 0; i < n; ++i)
      if (free_[static_cast<std::size_t>(i)]) f.push_back(i);
    const int m = static_cast<int>(f.size());
    if (m > 0) {
      Eigen::MatrixXd hf(m, m);
      Eigen::VectorXd r(m);
      for (int a = 0; a < m; ++a) {
        r[a] = q[f[static_cast<std::size_t>(a)]];
        for (int j = 0; j < n; ++j)
          if (!free_[static_cast<std::size_t>(j)]) r[a] -= h(f[static_cast<std::size_t>(a)], j) * x[j];
        for (int b = 0; b < m; ++b) hf(a, b) = h(f[static_cast<std::size_t>(a)], f[static_cast<std::size_t>(b)]);
      }
      const Eigen::VectorXd xf = hf.llt().solve(r);
      double t = 1;
      int block = -1;
      for (int a = 0; a < m; ++a) {
        const int i = f[static_cast<std::size_t>(a)];
        const double d = xf[a] - x[i];
        if (xf[a] < 0 && d < 0 && -x[i] / d < t) { t = -x[i] / d; block = i; }
        if (xf[a] > 1 && d > 0 && (1 - x[i]) / d < t) { t = (1 - x[i]) / d; block = i; }
      }
      for (int a = 0; a < m; ++a) x[f[static_cast<std::size_t>(a)]] += t * (xf[a] - x[f[static_cast<std::size_t>(a)]]);
      if (block >= 0) {
        x[block] = xf[std::find(f.begin(), f.end(), block) - f.begin()] < 0 ? 0.0 : 1.0;
        free_[static_cast<std::size_t>(block)] = 0;
        continue;
      }
    }
    const Eigen::VectorXd g = h * x - q;
    int worst = -1;
    double wv = 1e-12;
    for (int i = 0; i < n; ++i) {
      if (free_[static_cast<std::size_t>(i)]) continue;
      const double v = x[i] == 0 ? -g[i] : g[i];
      if (v > wv) { wv = v; worst = i; }
    }
    if (worst < 0) break;
    free_[static_cast<std::size_t>(worst)] = 1;
  }
  return x;
}

void BM_ArkitFit_PrimalRefactor_60s(benchmark::State& state) {
  NEED_VOICE(state);
  const Eigen::MatrixXd& h = fx->fit.gram();
  const int n = static_cast<int>(h.rows());
  double worst = 0;
  const ArkitTrack reference = fx->fit.fit(fx->frames, Eigen::MatrixXf());
  for (auto _ : state) {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    std::vector<char> free_(static_cast<std::size_t>(n), 0);
    for (Eigen::Index f = 0; f < fx->frames.rows(); ++f) {
      const Eigen::VectorXd q = h * fx->fit.unconstrained(fx->frames.row(f).transpose().cast<double>());
      x = primal_refactor(h, q, x, free_);
      for (int j = 0; j < n; ++j)
        worst = std::max(worst, std::abs(x[j] - reference.weights(f, fx->fit.columns()[static_cast<std::size_t>(j)])));
    }
    benchmark::DoNotOptimize(x.data());
  }
  state.counters["max_weight_difference"] = worst;  // the same minimiser (float output)
}

void BM_ArkitFit_Unfactored_60s(benchmark::State& state) {
  NEED_VOICE(state);
  const int n = static_cast<int>(fx->shapes.cols());
  const BoxQp qp(fx->fit.gram(), Eigen::VectorXd::Zero(n), Eigen::VectorXd::Ones(n));
  Eigen::VectorXd d, q;
  for (auto _ : state) {
    BoxQp::WarmStart warm;
    for (Eigen::Index f = 0; f < fx->frames.rows(); ++f) {
      d.noalias() = fx->offset + fx->components * fx->frames.row(f).transpose().cast<double>();  // the face
      q.noalias() = fx->shapes.transpose() * d;                                                   // projected
      benchmark::DoNotOptimize(qp.solve_from_unconstrained(qp.inverse() * q, warm).data());
    }
  }
  state.counters["region_rows"] = static_cast<double>(fx->shapes.rows());
}

void BM_ArkitFit_Build(benchmark::State& state) {
  NEED_VOICE(state);
  const FaceModel& face = ict_face_model();
  for (auto _ : state) {
    ArkitFit fit(face, fx->voice);
    benchmark::DoNotOptimize(&fit);
  }
}

void BM_MouthVisemes_60s(benchmark::State& state) {
  NEED_VOICE(state);
  const MouthVisemes visemes(fx->fit, fx->voice);
  const ArkitTrack t = fx->fit.fit(fx->frames, Eigen::MatrixXf());
  std::vector<Phone> phones(static_cast<std::size_t>(t.weights.rows()), Phone::AA);
  for (std::size_t i = 0; i < phones.size(); ++i) phones[i] = static_cast<Phone>(i / 6 % 40);  // 100 ms phones
  for (auto _ : state) {
    benchmark::DoNotOptimize(visemes.oculus(t.weights, phones).data());
    benchmark::DoNotOptimize(visemes.vrm(t.weights).data());
  }
}

BENCHMARK(BM_ArkitFit_60s)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ArkitFit_PrimalRefactor_60s)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ArkitFit_Unfactored_60s)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ArkitFit_Build)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MouthVisemes_60s)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace fapcast

BENCHMARK_MAIN();
