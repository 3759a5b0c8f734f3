#pragma once
// A registry of `fapcast` sub-commands, so that each command lives in its own file. A command
// file defines
//
//   static const fapcast::cli::Registration reg{"fap", [](CLI::App& app) { ... }};
//
// where the lambda adds its sub-command(s) to the top-level app and sets their callbacks, and the
// name is the command's ("fap", "voice build"), listed in kCommandOrder (main.cpp) at its place in
// the pipeline: --help lists the commands in that order, and a name missing there is a bug that
// stops fapcast at start-up. Callbacks report bad input by throwing (InputError or another
// std::runtime_error: exit 1) and usage mistakes by UsageError (exit 2); anything else is an
// internal error (exit 70): exit_status.hpp.
#include <CLI/CLI.hpp>

#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace fapcast::cli {

using AddCommand = std::function<void(CLI::App& top)>;

struct Registration {
  Registration(std::string_view command, AddCommand add);
};

// The group `name` of sub-commands ("corpus", "voice" ...): created by whichever command file
// registers first, found by the others.
CLI::App* command_group(CLI::App& top, const std::string& name, const std::string& description);

// The help line of the "eval" group (every `eval` command passes it).
inline constexpr const char* kEvalGroupHelp =
    "Evaluate retargeting and synthesis by the paper's measures, and the aligner against reference labels";

// The registered commands in pipeline order (kCommandOrder). Throws std::logic_error naming a
// registered command the order does not list, or one registered twice.
std::vector<AddCommand> registered_commands();

// Flushes standard output: kOk, or kBadInput with a message when the output could not be
// written (a full disk, a closed pipe). main() returns it after a command succeeded.
int standard_output_written();

// Thrown by a command for a usage mistake CLI11 cannot see (e.g. an unsupported extension).
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace fapcast::cli
