#pragma once
// What every command that writes a .fap shares: `--player xface|greta|vreng` (spec/fap-text.md,
// "Players") and the notes the writer has for the user.
#include "fapcast/codec/fap_text.hpp"

#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>
#include <vector>

namespace fapcast::cli {

// Adds --player to `cmd`, into `player` (empty: the strict standard layout).
CLI::Option* add_player_option(CLI::App* cmd, std::string& player);
// The write options for `player` (empty or a name add_player_option accepted).
FapTextWriteOptions fap_write_options(const std::string& player, FapTextDialect dialect = FapTextDialect::kStrict);
// Prints each note as "fapcast: note: PATH: NOTE" on standard error.
void print_notes(const std::filesystem::path& path, const std::vector<std::string>& notes);

}  // namespace fapcast::cli
