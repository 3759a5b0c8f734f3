#include "default_voice.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <iostream>
#include <stdexcept>
#include <vector>

#include "fapcast/core/data_root.hpp"
#include "fapcast/builder/voice_build.hpp"
#include "fapcast/core/file_io.hpp"
#include "default_voice_key.hpp"

#ifndef FAPCAST_VERSION
#define FAPCAST_VERSION "unknown"
#endif

namespace fapcast::cli {
namespace fs = std::filesystem;
namespace {

std::string env(const char* name) {
  const char* v = std::getenv(name);
  return v ? std::string(v) : std::string();
}

// The reference corpus the default voice is built from.
constexpr std::uint64_t kDefaultVoiceSeed = 1;

extern "C" char** environ;

// Records the reference corpus into `corpus` in a child process (`fapcast corpus
// record-reference`). espeak-ng 1.51 carries synthesiser state from call to call (its pitch
// flutter's phase, a function-local static no call resets), so speech shifts by a few samples
// with whatever the process spoke before: recorded in the calling process, the corpus (and the
// cached voice) would depend on the text that first needed it. A fresh process speaks the
// script from espeak-ng's initial state, every time. The child's summary line goes nowhere
// (standard output may be the caller's track); its progress and errors go to standard error.
void record_reference_corpus_in_child(const fs::path& corpus, bool quiet) {
  const std::string exe = fs::read_symlink("/proc/self/exe").string();
  std::vector<std::string> args = {exe, "corpus", "record-reference", "-o", corpus.string(),
                                   "--seed", std::to_string(kDefaultVoiceSeed),
                                   "--cmudict", default_cmudict_path().string(),
                                   "--word-counts", default_word_counts_path().string()};
  if (quiet) args.emplace_back("-q");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, exe.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0)
    throw std::runtime_error("default voice: cannot start " + exe + " to record the reference corpus: " +
                             std::strerror(spawned));
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error(std::string("default voice: waitpid: ") + std::strerror(errno));
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return;
  throw std::runtime_error("default voice: recording the reference corpus failed (" +
                           (WIFEXITED(status) ? "exit status " + std::to_string(WEXITSTATUS(status))
                                              : "signal " + std::to_string(WTERMSIG(status))) +
                           ")");
}

}  // namespace

fs::path default_voice_path() {
  fs::path dir;
  if (const std::string cache = env("FAPCAST_CACHE_DIR"); !cache.empty()) {
    dir = cache;
  } else if (const std::string xdg = env("XDG_CACHE_HOME"); !xdg.empty()) {
    dir = fs::path(xdg) / "fapcast";
  } else if (const std::string home = env("HOME"); !home.empty()) {
    dir = fs::path(home) / ".cache" / "fapcast";
  } else {
    throw std::runtime_error("default voice: set FAPCAST_CACHE_DIR, XDG_CACHE_HOME or HOME (no cache directory)");
  }
  return dir / ("reference-seed" + std::to_string(kDefaultVoiceSeed) + "-" + default_voice_key(kDefaultVoiceSeed) + ".fapv");
}

std::string voice_build_time_utc() {
  std::time_t t = 0;
  if (const std::string epoch = env("SOURCE_DATE_EPOCH"); !epoch.empty()) {
    std::size_t used = 0;
    long long seconds = -1;
    try {
      seconds = std::stoll(epoch, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != epoch.size() || seconds < 0)
      throw std::runtime_error("SOURCE_DATE_EPOCH=\"" + epoch + "\" is not a non-negative whole number of seconds");
    t = static_cast<std::time_t>(seconds);
  } else {
    t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  }
  std::tm utc{};
  gmtime_r(&t, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

fs::path ensure_default_voice(bool quiet) {
  const fs::path path = default_voice_path();
  if (fs::exists(path)) return path;
  fs::create_directories(path.parent_path());
  const fs::path corpus = fs::temp_directory_path() / ("fapcast-reference-corpus-" + std::to_string(::getpid()));
  struct Cleanup {  // the corpus is scratch: removed on success and on failure
    fs::path dir;
    ~Cleanup() {
      std::error_code ignored;
      fs::remove_all(dir, ignored);
    }
  } cleanup{corpus};
  if (!quiet) std::cerr << "building the default voice (SYNTHETIC reference talker, seed 1) into " << path.string() << "\n";
  record_reference_corpus_in_child(corpus, quiet);
  VoiceBuildOptions build;
  build.seed = kDefaultVoiceSeed;
  build.corpus_name = "fapcast reference corpus (SYNTHETIC), seed 1, all script items";
  build.build_time_utc = voice_build_time_utc();
  build.tool_version = FAPCAST_VERSION;
  build.progress = [&](std::string_view stage, std::size_t done, std::size_t total) {
    if (!quiet && (stage != "read" || done % 50 == 0 || done == total))
      std::cerr << "\rvoice build: " << stage << " " << done << " / " << total << "      " << std::flush;
  };
  const BuiltVoice voice = build_voice(corpus, build);
  if (!quiet) std::cerr << "\n";
  write_file_atomically(path, voice.bytes);
  return path;
}

Voice open_voice_or_default(const std::filesystem::path& path, bool quiet) {
  return Voice::open(path.empty() ? ensure_default_voice(quiet) : path);
}

}  // namespace fapcast::cli
