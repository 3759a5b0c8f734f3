#include "support/run_command.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <utility>
#include <vector>

namespace fapcast::test {

namespace fs = std::filesystem;

namespace {
// The directories make_temp_dir handed out, removed when the test process exits: /tmp is not
// cleaned on the machines CI runs on, and a suite run leaves hundreds of them otherwise.
class TempDirs {
 public:
  ~TempDirs() {
    for (const auto& dir : dirs_) {
      std::error_code ignored;  // a test may have removed it already
      fs::remove_all(dir, ignored);
    }
  }
  void add(std::string dir) { dirs_.push_back(std::move(dir)); }

 private:
  std::vector<std::string> dirs_;
};
TempDirs& temp_dirs() {
  static TempDirs dirs;
  return dirs;
}
}  // namespace

std::string make_temp_dir(const std::string& tag) {
  std::string pattern = (fs::temp_directory_path() / ("fapcast-" + tag + "-XXXXXX")).string();
  if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
  temp_dirs().add(pattern);
  return pattern;
}

CommandResult run_command(const std::string& command) {
  const std::string dir = make_temp_dir("cmd");
  const std::string out_path = dir + "/out", err_path = dir + "/err";
  const std::string full =
      command + " </dev/null >'" + out_path + "' 2>'" + err_path + "'";
  const int status = std::system(full.c_str());
  CommandResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  auto slurp = [](const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  };
  r.out = slurp(out_path);
  r.err = slurp(err_path);
  fs::remove_all(dir);
  return r;
}

}  // namespace fapcast::test
