#include "usage_hints.hpp"

#include <algorithm>
#include <cstddef>
#include <string_view>

namespace fapcast::cli {
namespace {

// Optimal string alignment distance (insertions, deletions, substitutions, adjacent swaps).
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

// The command the arguments were parsed into: the deepest subcommand given.
const CLI::App& parsed_command(const CLI::App& app) {
  const CLI::App* at = &app;
  for (;;) {
    const auto subs = at->get_subcommands();
    if (subs.empty()) return *at;
    at = subs.front();
  }
}

// The long option names ("obj-frames-out") of `command` and its parents.
std::vector<std::string> long_names(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::App* at = &command; at != nullptr; at = at->get_parent())
    for (const CLI::Option* option : at->get_options())
      for (const std::string& name : option->get_lnames()) names.push_back(name);
  return names;
}

// "eval articulography": the command's words after "fapcast".
std::string command_path(const CLI::App& command) {
  std::string path;
  for (const CLI::App* at = &command; at->get_parent() != nullptr; at = at->get_parent())
    path = at->get_name() + (path.empty() ? "" : " " + path);
  return path;
}

// "fapcast animate SPEECH [ALIGNMENT]": the command and its positionals; empty when it has none.
std::string positional_usage(const CLI::App& command) {
  std::string inputs;
  for (const CLI::Option* option : command.get_options())
    if (option->get_positional())
      inputs += option->get_required() ? " " + option->get_name() : " [" + option->get_name() + "]";
  return inputs.empty() ? std::string() : "fapcast " + command_path(command) + inputs;
}

}  // namespace

std::vector<std::string> unknown_option_hints(const CLI::App& app, const std::vector<std::string>& args) {
  const CLI::App& command = parsed_command(app);
  if (&command == &app) return {};
  const std::vector<std::string> names = long_names(command);
  std::vector<std::string> hints;
  bool any_unplaced = false;  // an unknown option with no near name: perhaps an input
  for (const std::string& arg : args) {
    if (arg.size() < 3 || arg.rfind("--", 0) != 0) continue;
    const std::size_t equals = arg.find('=');  // --name=value
    const std::string name = arg.substr(2, equals == std::string::npos ? std::string::npos : equals - 2);
    if (name.empty() || std::find(names.begin(), names.end(), name) != names.end()) continue;
    std::vector<std::string> near;
    for (const std::string& candidate : names)
      if ((candidate.rfind(name, 0) == 0 && candidate != "help") ||
          edit_distance(name, candidate) <= (name.size() <= 4 ? 1u : 2u))  // short names: one slip
        near.push_back("--" + candidate);
    if (near.empty()) any_unplaced = true;
    std::string hint = "--" + name + " is not an option of '" + command_path(command) + "'";
    for (std::size_t i = 0; i < near.size(); ++i)
      hint += (i == 0 ? "; did you mean " : i + 1 == near.size() ? " or " : ", ") + near[i];
    hints.push_back(hint + (near.empty() ? "" : "?"));
  }
  if (const std::string usage = positional_usage(command); any_unplaced && !usage.empty())
    hints.push_back("its inputs are positional: " + usage);
  return hints;
}

}  // namespace fapcast::cli
