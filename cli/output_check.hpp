#pragma once
// What a command that writes a file does before its work (spec/cli.md, "The output is -o"): learn
// that the output can be written, so a long run is not thrown away at its end.
#include <filesystem>

namespace fapcast::cli {

// Creates the output's temporary file beside `path` and removes it again (AtomicFile): throws
// std::runtime_error naming `path` (exit 1) when it cannot be written there - a missing or
// read-only folder. An empty path (standard output) is not checked.
void check_output_writable(const std::filesystem::path& path);

}  // namespace fapcast::cli
