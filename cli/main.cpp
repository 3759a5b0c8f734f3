// fapcast: speech to MPEG-4 facial animation. See README.md.
#include "command.hpp"

#include <algorithm>
#include <exception>
#include <iostream>
#include <map>
#include <string>

namespace fapcast::cli {
namespace {
std::multimap<std::string, AddCommand>& registry() {
  static std::multimap<std::string, AddCommand> commands;
  return commands;
}

// Prints an exception and the ones nested inside it, outermost first: "a: b: c".
void print_chain(std::ostream& out, const std::exception& e, bool first = true) {
  out << (first ? "" : ": ") << e.what();
  try {
    std::rethrow_if_nested(e);
  } catch (const std::exception& inner) {
    print_chain(out, inner, false);
  } catch (...) {
    out << ": unknown error";
  }
}
}  // namespace

Registration::Registration(std::string_view order_key, AddCommand add) {
  registry().emplace(std::string(order_key), std::move(add));
}

CLI::App* command_group(CLI::App& top, const std::string& name, const std::string& description) {
  for (CLI::App* sub : top.get_subcommands([](CLI::App*) { return true; }))
    if (sub->get_name() == name) return sub;
  CLI::App* group = top.add_subcommand(name, description);
  group->require_subcommand(1);
  return group;
}

std::vector<AddCommand> registered_commands() {
  std::vector<AddCommand> out;
  for (auto& [key, add] : registry()) out.push_back(add);
  return out;
}
}  // namespace fapcast::cli

int main(int argc, char** argv) {
  using namespace fapcast::cli;
  CLI::App app{"fapcast: speech to MPEG-4 facial animation (synthesis, .fap/FBA codec, RTP)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("fapcast ") + FAPCAST_VERSION);
  for (const auto& add : registered_commands()) add(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version arrive here too, with exit code 0.
    const int code = app.exit(e);
    return code == 0 ? kOk : kBadUsage;
  } catch (const UsageError& e) {
    std::cerr << "fapcast: usage: " << e.what() << "\n";
    return kBadUsage;
  } catch (const std::exception& e) {
    std::cerr << "fapcast: error: ";
    print_chain(std::cerr, e);
    std::cerr << "\n";
    return kBadInput;
  }
  return kOk;
}
