#pragma once
// What to say after CLI11 refuses an option the command does not have: the command's options
// that are near it in spelling ("--obj-frames": did you mean --obj-frames-out?), and, when the
// command reads files, that its inputs are positional (spec/cli.md, "The convention"), so that
// `animate --wav a.wav` is answered with `animate SPEECH [ALIGNMENT]`.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace fapcast::cli {

// Hint lines (without "fapcast: ") for the arguments of `argv` (argv[0] excluded) that start
// with "--" and name no option of the command `app` parsed them into (the deepest subcommand
// parsed); empty when there is none.
std::vector<std::string> unknown_option_hints(const CLI::App& app, const std::vector<std::string>& args);

}  // namespace fapcast::cli
