// Corpus importers' speed, each beside the obvious alternative in the same run:
// - C3D: read_c3d (every offset checked, labels, mask, mm) vs. a raw memcpy of the float block
//   (the floor: no validation at all).
// - TextGrid: read_textgrid vs. a naive std::regex line matcher of the long form (what a
//   script would do; it checks nothing and keeps only intervals).
#include "fapcast/corpus/c3d.hpp"
#include "fapcast/corpus/textgrid.hpp"

#include <benchmark/benchmark.h>

#include <cstring>
#include <random>
// GCC 12 warns falsely (-Wmaybe-uninitialized) inside libstdc++'s <regex> at -O1 with ASan;
// the regex parser here is only the naive baseline the TextGrid reader is compared against.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <regex>
#include <sstream>

namespace {

using namespace fapcast;

// 10 s of 60 markers at 60 fps (one utterance-sized take is ~2 s; this is a long one).
std::string c3d_take() {
  std::mt19937_64 rng(7);
  MarkerFrames<Millimetres> m = MarkerFrames<Millimetres>::zeros(60, 600);
  std::uniform_real_distribution<float> mm(-200.0F, 200.0F);
  for (Eigen::Index i = 0; i < 60; ++i) m.labels[static_cast<std::size_t>(i)] = "M" + std::to_string(i);
  for (Eigen::Index f = 0; f < 600; ++f) {
    for (Eigen::Index i = 0; i < 60; ++i) m.set(i, f, Eigen::Vector3d(mm(rng), mm(rng), mm(rng)));
  }
  return write_c3d(m, {c3d_synthetic_parameter()});
}

void BM_C3dRead(benchmark::State& state) {
  const std::string bytes = c3d_take();
  for (auto _ : state) benchmark::DoNotOptimize(read_c3d(bytes, "bench.c3d"));
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes.size()));
}
BENCHMARK(BM_C3dRead);

void BM_C3dRawCopyBaseline(benchmark::State& state) {
  const std::string bytes = c3d_take();
  const std::size_t data_block = static_cast<unsigned char>(bytes[16]) | static_cast<unsigned char>(bytes[17]) << 8;
  const std::size_t at = (data_block - 1) * 512;
  for (auto _ : state) {
    std::vector<float> values((bytes.size() - at) / 4);
    std::memcpy(values.data(), bytes.data() + at, values.size() * 4);
    benchmark::DoNotOptimize(values.data());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes.size()));
}
BENCHMARK(BM_C3dRawCopyBaseline);

// Phones and words of ~3 minutes of speech: 2000 phone intervals, 600 word intervals.
std::string textgrid_text() {
  Alignment a;
  a.end_s = 200;
  LabelTier phones{"phones", TierKind::intervals, 0, 200, {}, {}};
  LabelTier words{"words", TierKind::intervals, 0, 200, {}, {}};
  for (int i = 0; i < 2000; ++i) phones.intervals.push_back({i * 0.1, (i + 1) * 0.1, i % 7 ? "ah" : ""});
  for (int i = 0; i < 600; ++i) words.intervals.push_back({i / 3.0, (i + 1) / 3.0, "word"});
  a.tiers = {phones, words};
  return write_textgrid(a);
}

void BM_TextGridRead(benchmark::State& state) {
  const std::string text = textgrid_text();
  for (auto _ : state) benchmark::DoNotOptimize(read_textgrid(text, "bench.TextGrid"));
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
}
BENCHMARK(BM_TextGridRead);

void BM_TextGridRegexBaseline(benchmark::State& state) {
  const std::string text = textgrid_text();
  const std::regex number(R"(^\s*(xmin|xmax) = ([-0-9.eE]+)\s*$)");
  const std::regex label(R"re(^\s*text = "(.*)"\s*$)re");
  for (auto _ : state) {
    std::istringstream in(text);
    std::string line;
    std::vector<Interval> intervals;
    Interval current;
    std::smatch m;
    while (std::getline(in, line)) {
      if (std::regex_match(line, m, number)) {
        (m[1] == "xmin" ? current.start_s : current.end_s) = std::stod(m[2]);
      } else if (std::regex_match(line, m, label)) {
        current.label = m[1];
        intervals.push_back(current);
      }
    }
    benchmark::DoNotOptimize(intervals.data());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
}
BENCHMARK(BM_TextGridRegexBaseline);

}  // namespace

BENCHMARK_MAIN();
