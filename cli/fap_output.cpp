#include "fap_output.hpp"

#include <iostream>

namespace fapcast::cli {

CLI::Option* add_player_option(CLI::App* cmd, std::string& player) {
  return cmd
      ->add_option("--player", player,
                   ".fap output for one player's own parser: xface (FAP 1/2 as 4/6 fields, whole fps), greta or "
                   "vreng (FAP 1/2 one field each); default: the strict standard layout")
      ->check(CLI::IsMember({"xface", "greta", "vreng"}));
}

FapTextWriteOptions fap_write_options(const std::string& player, FapTextDialect dialect) {
  FapTextWriteOptions o;
  o.dialect = dialect;
  if (!player.empty()) o.player = fap_player_from_name(player);
  return o;
}

void print_notes(const std::filesystem::path& path, const std::vector<std::string>& notes) {
  for (const std::string& n : notes) std::cerr << "fapcast: note: " << path.string() << ": " << n << "\n";
}

}  // namespace fapcast::cli
