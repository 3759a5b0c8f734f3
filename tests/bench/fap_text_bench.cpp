// Reading and writing speed of .fap text (frames per second) on a long SYNTHETIC sequence
// (100,000 frames, Xface's 50-FAP mask), against the obvious alternative in the same run:
// a std::istringstream >> parser and a std::ostringstream << writer. After the runs it prints
// the ratios of CPU times (spec/fap-text.md records them).
#include "fapcast/codec/fap_text.hpp"
#include "support/fap_sequences.hpp"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>

namespace {
using namespace fapcast;

constexpr std::size_t kFrames = 100'000;

const FapSequence& sequence() {
  static const FapSequence s = test::realistic_fap_sequence(kFrames);
  return s;
}

const std::string& text() {
  static const std::string t = write_fap_text(sequence());
  return t;
}

// The obvious reader: stream extraction, strict dialect only, no checks beyond stream state.
FapSequence naive_read(const std::string& bytes) {
  std::istringstream in(bytes);
  FapSequence s;
  std::string version;
  std::uint64_t count = 0;
  in >> version >> s.name >> s.rate.numerator >> count;
  for (std::uint64_t k = 0; k < count && in; ++k) {
    FapFrame f;
    for (int n = 1; n <= kFapCount; ++n) {
      int bit = 0;
      in >> bit;
      f.mask.set(n, bit == 1);
    }
    std::uint64_t frame = 0;
    in >> frame;
    int v = 0;
    if (f.mask.test(kVisemeFap)) {
      in >> v; f.viseme.select1 = static_cast<std::uint8_t>(v);
      in >> v; f.viseme.select2 = static_cast<std::uint8_t>(v);
      in >> v; f.viseme.blend = static_cast<std::uint8_t>(v);
      in >> v; f.viseme.def = v != 0;
    }
    if (f.mask.test(kExpressionFap)) {
      in >> v; f.expression.select1 = static_cast<std::uint8_t>(v);
      in >> v; f.expression.intensity1 = static_cast<std::uint8_t>(v);
      in >> v; f.expression.select2 = static_cast<std::uint8_t>(v);
      in >> v; f.expression.intensity2 = static_cast<std::uint8_t>(v);
      in >> v; f.expression.init_face = v != 0;
      in >> v; f.expression.def = v != 0;
    }
    for (int n = kFirstLowLevelFap; n <= kFapCount; ++n)
      if (f.mask.test(n)) in >> f.values[static_cast<std::size_t>(n - 1)];
    s.frames.push_back(f);
  }
  return s;
}

// The obvious writer: stream insertion.
std::string naive_write(const FapSequence& s) {
  std::ostringstream out;
  out << "2.1 " << s.name << ' ' << s.rate.numerator << ' ' << s.frames.size() << '\n';
  for (std::size_t k = 0; k < s.frames.size(); ++k) {
    const auto& f = s.frames[k];
    for (int n = 1; n <= kFapCount; ++n) out << f.mask.test(n) << (n == kFapCount ? '\n' : ' ');
    out << k;
    for (int n = kFirstLowLevelFap; n <= kFapCount; ++n)
      if (f.mask.test(n)) out << ' ' << f.value(n);
    out << '\n';
  }
  return out.str();
}

void frames_per_second(benchmark::State& state) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kFrames));
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text().size()));
}

void BM_Read_fapcast(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(read_fap_text(text(), "bench.fap"));
  frames_per_second(state);
}
void BM_Read_istringstream(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(naive_read(text()));
  frames_per_second(state);
}
void BM_Write_fapcast(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(write_fap_text(sequence()));
  frames_per_second(state);
}
void BM_Write_ostringstream(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(naive_write(sequence()));
  frames_per_second(state);
}
BENCHMARK(BM_Read_fapcast)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Read_istringstream)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Write_fapcast)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Write_ostringstream)->Unit(benchmark::kMillisecond);

// Console output plus the time of each benchmark, for the ratios printed at the end.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  RatioReporter() : ConsoleReporter(OO_Tabular) {}  // no colour codes: figures get pasted
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    // CPU time (the machine is shared); with --benchmark_repetitions, the mean.
    for (const auto& r : runs)
      if (r.run_type == Run::RT_Iteration || r.aggregate_name == "mean")
        seconds_[r.run_name.function_name] = r.GetAdjustedCPUTime();
  }
  double ratio(const std::string& slow, const std::string& fast) const {
    const auto a = seconds_.find(slow), b = seconds_.find(fast);
    return a == seconds_.end() || b == seconds_.end() ? 0.0 : a->second / b->second;
  }

 private:
  std::map<std::string, double> seconds_;
};

}  // namespace

int main(int argc, char** argv) {
  // Both readers and both writers must agree before their speeds mean anything.
  if (naive_read(text()).frames != sequence().frames || naive_write(sequence()) != text()) {
    std::fprintf(stderr, "the naive reader/writer disagrees with fapcast\n");
    return 1;
  }
  benchmark::Initialize(&argc, argv);
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  std::printf("read:  fapcast is %.2fx the speed of std::istringstream >>\n",
              reporter.ratio("BM_Read_istringstream", "BM_Read_fapcast"));
  std::printf("write: fapcast is %.2fx the speed of std::ostringstream <<\n",
              reporter.ratio("BM_Write_ostringstream", "BM_Write_fapcast"));
  return 0;
}
