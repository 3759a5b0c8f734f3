// The whole voice build (voice_build.hpp) on the SYNTHETIC reference corpus onto the full ICT
// face (D = 80,157): the exact PCA route on the full corpus, and the exact route against EM-PCA on
// the same subset of utterances (EM-PCA's time is linear in frames x iterations; the full-corpus
// EM figure is extrapolated from the subset, see spec/voice.md). Peak memory: VmHWM of this
// process, reset per benchmark.
//
// The corpus is recorded once into a temporary directory (about 3 s), or taken from
// $FAPCAST_BENCH_CORPUS when set.
#include <benchmark/benchmark.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <span>
#include <fstream>
#include <string>

#include "fapcast/core/data_root.hpp"
#include "fapcast/math/pca_basis.hpp"
#include "fapcast/corpus/recording_script.hpp"
#include "fapcast/talker/reference_talker.hpp"
#include "fapcast/corpus/syllabified_lexicon.hpp"
#include "fapcast/builder/voice_build.hpp"
#include "fapcast/voice/voice_file.hpp"
#include "fapcast/core/file_io.hpp"

namespace {

namespace fs = std::filesystem;
using namespace fapcast;

constexpr std::size_t kSubsetUtterances = 30;

struct Corpora {
  fs::path full;
  fs::path subset;  // the first kSubsetUtterances takes, scanned (no manifest)
  bool owned = false;
  ~Corpora() {
    std::error_code ignored;
    if (owned) fs::remove_all(full, ignored);
    fs::remove_all(subset, ignored);
  }
};

const Corpora& corpora() {
  static const Corpora c = [] {
    Corpora out;
    if (const char* given = std::getenv("FAPCAST_BENCH_CORPUS"); given != nullptr && *given != '\0') {
      out.full = given;
    } else {
      out.owned = true;
      out.full = fs::temp_directory_path() / ("fapcast_bench_reference_" + std::to_string(::getpid()));
      const auto lexicon = parse_festival_lexicon(fapcast::read_file(default_cmudict_path()), "cmudict");
      const auto counts = parse_word_counts(fapcast::read_file(default_word_counts_path()), "word counts");
      (void)record_reference_corpus(build_recording_script(counts, lexicon), out.full, {},
                                    [&](const std::string& name, std::string_view bytes) {
                                      fapcast::write_file_atomically(out.full / name, bytes);
                                    });
    }
    out.subset = fs::temp_directory_path() / ("fapcast_bench_subset_" + std::to_string(::getpid()));
    fs::create_directories(out.subset);
    for (std::size_t i = 1; i <= kSubsetUtterances; ++i) {
      char stem[16];
      std::snprintf(stem, sizeof stem, "utt%04zu", i);
      for (const char* ext : {".c3d", ".TextGrid"})
        fs::copy_file(out.full / (std::string(stem) + ext), out.subset / (std::string(stem) + ext),
                      fs::copy_options::overwrite_existing);
    }
    return out;
  }();
  return c;
}

void reset_peak_memory() { std::ofstream("/proc/self/clear_refs") << "5"; }

double peak_memory_mb() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return -1;
}

// The PCA components (D x k) of a built voice.
Eigen::MatrixXd components_of(const std::string& bytes) {
  const auto view = VoiceFileView::over_bytes(std::as_bytes(std::span(bytes)), "<bench voice>");
  return view.matrix_f32(voice_section::kPcaComponents).transpose().cast<double>();
}

// EM-PCA passes in the subset benchmark: its time is linear in passes, so the figure per pass
// extrapolates (a run with the default cap of 300 passes had not finished after 11 minutes).
constexpr int kEmIterations = 20;

std::string run(benchmark::State& state, const fs::path& corpus, PcaRoute route) {
  VoiceBuildOptions options;
  options.pca = route;
  options.em_max_iterations = kEmIterations;
  options.build_time_utc = "bench";
  reset_peak_memory();
  VoiceBuildSummary s;
  std::string bytes;
  for (auto _ : state) {
    BuiltVoice v = build_voice(corpus, options);
    s = v.summary;
    bytes = std::move(v.bytes);
  }
  state.counters["frames"] = static_cast<double>(s.frames);
  state.counters["read_s"] = s.seconds_read;
  state.counters["fit_s"] = s.seconds_fit;
  state.counters["pca_s"] = s.seconds_pca;
  state.counters["pca_iterations"] = s.pca_iterations;
  state.counters["explained"] = s.explained_fraction;
  state.counters["voice_MB"] = static_cast<double>(bytes.size()) / 1e6;
  state.counters["peak_MB"] = peak_memory_mb();
  return bytes;
}

std::string& subset_exact_voice() {
  static std::string bytes;
  return bytes;
}

void BM_VoiceBuildFullExact(benchmark::State& state) { (void)run(state, corpora().full, PcaRoute::exact); }
void BM_VoiceBuildSubsetExact(benchmark::State& state) {
  subset_exact_voice() = run(state, corpora().subset, PcaRoute::exact);
}
// Also: the largest principal angle between the EM and exact routes' 17-dimensional subspaces.
void BM_VoiceBuildSubsetEm(benchmark::State& state) {
  const std::string em = run(state, corpora().subset, PcaRoute::em);
  if (!subset_exact_voice().empty())
    state.counters["max_angle_vs_exact_rad"] =
        principal_angles(components_of(em), components_of(subset_exact_voice())).maxCoeff();
}

BENCHMARK(BM_VoiceBuildFullExact)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
BENCHMARK(BM_VoiceBuildSubsetExact)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
BENCHMARK(BM_VoiceBuildSubsetEm)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
