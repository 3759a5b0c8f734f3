// `fapcast say` as a user runs it, against the espeak-ng command on the same page, in the same
// run: `fapcast say --text-file PAGE -o X.fap --wav-out X.wav` (process start, espeak-ng
// initialisation, the front-end, reading the default voice, the unit search, PCA -> FAPs, writing
// the .fap text and the WAV) against `espeak-ng -v en-us -f PAGE -w X.wav` (process start, its
// initialisation, synthesis, writing the WAV). Both are whole processes that turn the same text
// file into a WAV, so their difference is what fapcast adds; the library-level comparison (espeak_Synth
// to a buffer, no process, no files) is say_bench's BM_SayVsEspeak.
//
// Time is each child's CPU time (user + system, from wait4's rusage): robust on a shared
// machine, where wall time depends on the other jobs. BM_SayCommandVsEspeak runs both in every
// iteration and reports the ratio of their summed CPU times (say_over_espeak_cpu) and of their
// wall times. The page is tests/data/text/declaration-1776-page.txt (public domain); FAPCAST_PAGE
// names another text file, FAPCAST_PAGE_REPEAT=N speaks it N times over (one file of N copies).
// The default voice is read from the user's cache (built there on the warm-up run if absent).
#include <benchmark/benchmark.h>

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace {

namespace fs = std::filesystem;

struct ChildCost {
  double cpu_s = 0.0;   // user + system
  double wall_s = 0.0;
  double max_rss_mib = 0.0;  // peak resident set (ru_maxrss)
};

double seconds(const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); }

double wall_now() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Runs argv (stdout and stderr to /dev/null) and returns its CPU and wall time; throws when it
// cannot start or does not exit 0.
ChildCost run(const std::vector<std::string>& argv) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  const double t0 = wall_now();
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw std::runtime_error(argv[0] + ": cannot start");
  int status = 0;
  rusage usage{};
  if (wait4(pid, &status, 0, &usage) != pid) throw std::runtime_error(argv[0] + ": wait4 failed");
  const double t1 = wall_now();
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(argv[0] + " " + argv[1] + ": exited with status " + std::to_string(status));
  return {seconds(usage.ru_utime) + seconds(usage.ru_stime), t1 - t0, static_cast<double>(usage.ru_maxrss) / 1024.0};
}

struct Page {
  fs::path dir;
  fs::path text;
  double audio_s = 0.0;  // seconds of speech espeak-ng makes of it
};

// The page written once into a scratch folder (N copies when FAPCAST_PAGE_REPEAT=N).
// The page's text (FAPCAST_PAGE, else the declaration's page).
const std::string& page_bytes() {
  static const std::string text = [] {
    const char* named = std::getenv("FAPCAST_PAGE");
    const fs::path source = named != nullptr ? fs::path(named) : fs::path(FAPCAST_TEST_DATA) / "text/declaration-1776-page.txt";
    std::ifstream in(source, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    if (!in || bytes.str().empty()) throw std::runtime_error(source.string() + ": cannot read the page");
    return bytes.str();
  }();
  return text;
}

const Page& page() {
  static const Page p = [] {
    const char* repeat_text = std::getenv("FAPCAST_PAGE_REPEAT");
    const int repeat = repeat_text != nullptr ? std::max(1, std::atoi(repeat_text)) : 1;
    Page made;
    made.dir = fs::temp_directory_path() / ("fapcast_say_command_bench." + std::to_string(::getpid()));
    fs::create_directories(made.dir);
    made.text = made.dir / "page.txt";
    std::ofstream out(made.text, std::ios::binary);
    for (int i = 0; i < repeat; ++i) out << page_bytes() << "\n\n";
    out.close();
    return made;
  }();
  return p;
}

std::vector<std::string> espeak_argv() {
  return {"espeak-ng", "-v", "en-us", "-f", page().text.string(), "-w", (page().dir / "espeak.wav").string()};
}

std::vector<std::string> say_argv() {
  return {FAPCAST_EXE, "say", "--text-file", page().text.string(), "-o", (page().dir / "say.fap").string(),
          "--wav-out", (page().dir / "say.wav").string(), "-q"};
}

// Seconds of 16-bit mono speech in a WAV of the espeak-ng command (its header is 44 bytes).
double wav_seconds(const fs::path& wav, double rate_hz) {
  return static_cast<double>(fs::file_size(wav) - 44) / 2.0 / rate_hz;
}

void speech_rate(benchmark::State& state, double audio_s) {
  state.counters["speech_s"] = audio_s;
  state.counters["speech_s_per_s"] = benchmark::Counter(audio_s * static_cast<double>(state.iterations()),
                                                        benchmark::Counter::kIsRate);
}

// Runs once before the timed loops: builds the default voice if the cache has none, and fails
// early when either command does not run.
bool warm(benchmark::State& state) {
  static const std::string failure = [] {
    try {
      run(say_argv());
      run(espeak_argv());
      return std::string();
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
  }();
  if (!failure.empty()) state.SkipWithError(failure.c_str());
  return failure.empty();
}

// One command per iteration: its wall time as the iteration's, its CPU time as a counter.
void time_command(benchmark::State& state, std::vector<std::string> (*argv)(), const char* wav) {
  if (!warm(state)) return;
  double cpu = 0.0;
  for (auto _ : state) {
    const ChildCost c = run(argv());
    state.SetIterationTime(c.wall_s);
    cpu += c.cpu_s;
  }
  state.counters["child_cpu_ms"] = 1000.0 * cpu / static_cast<double>(state.iterations());
  speech_rate(state, wav_seconds(page().dir / wav, 22050.0));
}

void BM_EspeakCommand(benchmark::State& state) { time_command(state, espeak_argv, "espeak.wav"); }
BENCHMARK(BM_EspeakCommand)->Unit(benchmark::kMillisecond)->UseManualTime();

void BM_SayCommand(benchmark::State& state) { time_command(state, say_argv, "say.wav"); }
BENCHMARK(BM_SayCommand)->Unit(benchmark::kMillisecond)->UseManualTime();

// Both commands in every iteration (espeak-ng first), so a change of load hits both alike.
void BM_SayCommandVsEspeak(benchmark::State& state) {
  if (!warm(state)) return;
  ChildCost espeak, say;
  for (auto _ : state) {
    const ChildCost e = run(espeak_argv());
    const ChildCost s = run(say_argv());
    state.SetIterationTime(e.wall_s + s.wall_s);
    espeak.cpu_s += e.cpu_s;
    espeak.wall_s += e.wall_s;
    say.cpu_s += s.cpu_s;
    say.wall_s += s.wall_s;
  }
  const auto n = static_cast<double>(state.iterations());
  state.counters["espeak_cpu_ms"] = 1000.0 * espeak.cpu_s / n;
  state.counters["say_cpu_ms"] = 1000.0 * say.cpu_s / n;
  state.counters["say_over_espeak_cpu"] = say.cpu_s / espeak.cpu_s;
  state.counters["say_over_espeak_wall"] = say.wall_s / espeak.wall_s;
  state.counters["speech_s"] = wav_seconds(page().dir / "say.wav", 22050.0);
}
BENCHMARK(BM_SayCommandVsEspeak)->Unit(benchmark::kMillisecond)->UseManualTime();

// Peak memory (the child's ru_maxrss) of `fapcast say` on range(0) pages (copies of the page,
// as FAPCAST_PAGE_REPEAT makes them) to a .fap and its WAV: made in pieces as the speech comes
// (the default) and at once (--piece-seconds 0, the whole-text path), both in every iteration.
void BM_SayCommandMemory(benchmark::State& state) {
  if (!warm(state)) return;
  const auto pages = static_cast<int>(state.range(0));
  const fs::path text = page().dir / ("pages-" + std::to_string(pages) + ".txt");
  {
    std::ofstream out(text, std::ios::binary);
    for (int i = 0; i < pages; ++i) out << page_bytes() << "\n\n";
  }
  auto argv = [&](bool whole) {
    std::vector<std::string> a{FAPCAST_EXE, "say", "--text-file", text.string(), "-o", (page().dir / "mem.fap").string(),
                               "--wav-out", (page().dir / "mem.wav").string(), "-q"};
    if (whole) a.insert(a.end(), {"--piece-seconds", "0"});
    return a;
  };
  ChildCost pieces, whole;
  for (auto _ : state) {
    const ChildCost p = run(argv(false));
    const ChildCost w = run(argv(true));
    state.SetIterationTime(p.wall_s + w.wall_s);
    pieces.max_rss_mib = std::max(pieces.max_rss_mib, p.max_rss_mib);
    whole.max_rss_mib = std::max(whole.max_rss_mib, w.max_rss_mib);
    pieces.cpu_s += p.cpu_s;
    whole.cpu_s += w.cpu_s;
  }
  const auto n = static_cast<double>(state.iterations());
  state.counters["pages"] = pages;
  state.counters["speech_s"] = wav_seconds(page().dir / "mem.wav", 22050.0);
  state.counters["pieces_rss_mib"] = pieces.max_rss_mib;
  state.counters["whole_rss_mib"] = whole.max_rss_mib;
  state.counters["pieces_cpu_ms"] = 1000.0 * pieces.cpu_s / n;
  state.counters["whole_cpu_ms"] = 1000.0 * whole.cpu_s / n;
  state.counters["pieces_over_whole_cpu"] = pieces.cpu_s / whole.cpu_s;
}
BENCHMARK(BM_SayCommandMemory)->Arg(1)->Arg(8)->Arg(32)->Iterations(1)->Unit(benchmark::kMillisecond)->UseManualTime();

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  std::error_code ignored;
  fs::remove_all(page().dir, ignored);
  return 0;
}
