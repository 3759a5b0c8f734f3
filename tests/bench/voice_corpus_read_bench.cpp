// The voice build's corpus reading (voice_corpus.hpp: list_corpus, then read_corpus_take for
// every take, as build_voice's "read" stage does) on the same SYNTHETIC takes delivered four
// ways: C3D + TextGrid (as the reference talker writes them), TRC + .lab, marker CSV + .lab, and
// TRC at 120 fps + .lab (resampled to 60). Reported per 60 fps frame read; the ratio to C3D is
// the comparison (spec/corpus.md "Voice build reading speed").
//
// The corpus (60 common words, reference talker seed 5) is recorded once into a temporary
// directory and converted by tests/support/corpus_conversion.hpp.
#include <benchmark/benchmark.h>

#include <unistd.h>

#include <filesystem>
#include <string>

#include "fapcast/corpus/recording_script.hpp"
#include "fapcast/talker/reference_talker.hpp"
#include "fapcast/builder/voice_corpus.hpp"
#include "fapcast/core/file_io.hpp"
#include "support/corpus_conversion.hpp"

namespace {

namespace fs = std::filesystem;
using namespace fapcast;
using fapcast::test::AlignmentFormat;
using fapcast::test::MarkerFormat;

const char* const kWords[] = {"bob",  "five", "thin", "dad",  "see",   "lull",  "shoe", "red",   "go",    "we",
                              "it",   "bed",  "hat",  "father", "boy", "show",  "good", "moon",  "how",   "people",
                              "water", "about", "would", "little", "there", "which", "their", "other", "number", "could",
                              "sound", "write", "first", "thing", "mother", "answer", "picture", "yellow", "garden", "window",
                              "music", "family", "teacher", "morning", "summer", "river", "orange", "cheese", "juice", "bridge",
                              "zebra", "violin", "measure", "anthem", "wagon", "kitchen", "lemon", "puppy", "ocean", "jungle"};

struct Corpora {
  fs::path root;
  fs::path c3d, trc, csv, trc120;
  ~Corpora() {
    std::error_code ignored;
    fs::remove_all(root, ignored);
  }
};

const Corpora& corpora() {
  static const Corpora c = [] {
    Corpora out;
    out.root = fs::temp_directory_path() / ("fapcast_bench_corpus_read_" + std::to_string(::getpid()));
    out.c3d = out.root / "c3d";
    out.trc = out.root / "trc";
    out.csv = out.root / "csv";
    out.trc120 = out.root / "trc120";
    RecordingScript script;
    for (const char* w : kWords) script.items.push_back({ScriptSection::kCommonWord, w, {}, "", 0.0});
    (void)record_reference_corpus(script, out.c3d, {.count = 0, .seed = 5, .script = {}},
                                  [&](const std::string& name, std::string_view bytes) {
                                    fapcast::write_file_atomically(out.c3d / name, bytes);
                                  });
    fapcast::test::convert_corpus(out.c3d, out.trc, MarkerFormat::trc, AlignmentFormat::lab);
    fapcast::test::convert_corpus(out.c3d, out.csv, MarkerFormat::csv, AlignmentFormat::lab);
    fapcast::test::convert_corpus(out.c3d, out.trc120, MarkerFormat::trc, AlignmentFormat::lab, 2);
    return out;
  }();
  return c;
}

void read_corpus(benchmark::State& state, const fs::path& dir) {
  std::int64_t frames = 0;
  std::uintmax_t bytes = 0;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() != ".wav") bytes += e.file_size();
  for (auto _ : state) {
    const CorpusListing listing = list_corpus(dir);
    frames = 0;
    for (std::size_t u = 0; u < listing.utterances.size(); ++u) {
      const CorpusTake take = read_corpus_take(listing, u);
      frames += take.markers.frame_count();
      benchmark::DoNotOptimize(take.markers.positions.data());
    }
  }
  state.SetItemsProcessed(state.iterations() * frames);  // 60 fps frames
  state.counters["frames"] = static_cast<double>(frames);
  state.counters["corpus_KB"] = static_cast<double>(bytes) / 1024.0;
}

void BM_ReadC3dTextGrid(benchmark::State& state) { read_corpus(state, corpora().c3d); }
void BM_ReadTrcLab(benchmark::State& state) { read_corpus(state, corpora().trc); }
void BM_ReadCsvLab(benchmark::State& state) { read_corpus(state, corpora().csv); }
void BM_ReadTrc120FpsLab(benchmark::State& state) { read_corpus(state, corpora().trc120); }

BENCHMARK(BM_ReadC3dTextGrid)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadTrcLab)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadCsvLab)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadTrc120FpsLab)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
