#pragma once
// For fuzz targets of readers that take a path: a directory of this process's own under the
// temporary directory (removed at exit), and a file in it rewritten with each input.
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <sys/types.h>
#include <unistd.h>

namespace fapcast::fuzz {

// libFuzzer ends a timed run with _Exit, past atexit: so each process first removes the folders
// of fuzz processes that no longer run (fapcast-fuzz-PID with no process PID).
inline const std::filesystem::path& scratch_dir() {
  static const std::filesystem::path dir = [] {
    const auto tmp = std::filesystem::temp_directory_path();
    std::error_code ec;
    for (std::filesystem::directory_iterator it(tmp, ec), end; !ec && it != end; it.increment(ec)) {
      const std::string name = it->path().filename().string();
      if (name.rfind("fapcast-fuzz-", 0) != 0) continue;
      char* rest = nullptr;
      const long pid = std::strtol(name.c_str() + 13, &rest, 10);
      if (pid <= 0 || *rest != '\0') continue;
      if (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) {
        std::error_code ignored;
        std::filesystem::remove_all(it->path(), ignored);
      }
    }
    auto d = tmp / ("fapcast-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    std::atexit([] {
      std::error_code ignored;
      std::filesystem::remove_all(scratch_dir(), ignored);
    });
    return d;
  }();
  return dir;
}

// Writes `bytes` to scratch_dir()/name (creating its folders) and returns the path.
inline std::filesystem::path scratch_file(const std::string& name, std::string_view bytes) {
  const auto path = scratch_dir() / name;
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return path;
}

}  // namespace fapcast::fuzz
