#pragma once
// A registry of `fapcast` sub-commands, so that each command lives in its own file and main.cpp
// never changes when one is added. A command file defines
//
//   static const fapcast::cli::Registration reg{"fap", [](CLI::App& app) { ... }};
//
// where the lambda adds its sub-command(s) to the top-level app and sets their callbacks.
// Callbacks report bad input by throwing (any std::exception): main prints the chain of
// nested messages and exits 1. CLI11 usage errors exit 2.
#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace fapcast::cli {

using AddCommand = std::function<void(CLI::App& top)>;

struct Registration {
  Registration(std::string_view order_key, AddCommand add);
};

// The group `name` of sub-commands ("corpus", "voice" ...): created by whichever command file
// registers first, found by the others.
CLI::App* command_group(CLI::App& top, const std::string& name, const std::string& description);

// The registered commands, sorted by their order keys so that --help lists them stably.
std::vector<AddCommand> registered_commands();

// Exit codes of the command line.
enum ExitCode : int { kOk = 0, kBadInput = 1, kBadUsage = 2 };

// Thrown by a command for a usage mistake CLI11 cannot see (e.g. an unsupported extension).
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace fapcast::cli
