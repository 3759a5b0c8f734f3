#pragma once
// Runs a shell command for end-to-end tests and captures its exit code, stdout and stderr.
#include <string>

namespace fapcast::test {

struct CommandResult {
  int exit_code = -1;
  std::string out;  // standard output
  std::string err;  // standard error
};

// Runs `command` under /bin/sh. Standard input is /dev/null.
CommandResult run_command(const std::string& command);

// A fresh empty directory under the system's temporary directory, removed with everything in it
// when the test process exits.
std::string make_temp_dir(const std::string& tag);

}  // namespace fapcast::test
