// fapcast: speech to MPEG-4 facial animation. The commands: spec/cli.md.
#include "command.hpp"
#include "exit_status.hpp"
#include "usage_hints.hpp"

#include <malloc.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <map>
#include <string>
#include <string_view>

namespace fapcast::cli {
namespace {

// The commands in pipeline order, as --help lists them: recording and aligning speech, making a
// voice, speaking with it, measuring it, faces, the file formats, looking at a mesh, the network.
constexpr std::array<std::string_view, 23> kCommandOrder{
    "corpus script", "corpus record-reference",                       // the recording (paper 3.2)
    "align",                                                          // recorded speech's phones
    "voice build",   "voice info", "voice default", "voice adapt",    // the voice (3.3-3.6, 3.9)
    "say",           "animate",                                       // synthesis (3.7-3.8)
    "eval retarget", "eval synth", "eval align", "eval articulography",  // evaluation (4.1), the aligner, real talkers
    "adapt",         "expressions",                                   // faces (3.9)
    "fap",           "encode",      "decode",        "export",        // the file formats
    "render",                                                         // looking at a .glb
    "stream",        "recv",        "serve"};                         // the network

std::map<std::string, AddCommand, std::less<>>& registry() {
  static std::map<std::string, AddCommand, std::less<>> commands;
  return commands;
}
std::vector<std::string>& registered_twice() {
  static std::vector<std::string> names;
  return names;
}

}  // namespace

Registration::Registration(std::string_view command, AddCommand add) {
  if (!registry().emplace(std::string(command), std::move(add)).second) registered_twice().emplace_back(command);
}

CLI::App* command_group(CLI::App& top, const std::string& name, const std::string& description) {
  for (CLI::App* sub : top.get_subcommands([](CLI::App*) { return true; }))
    if (sub->get_name() == name) return sub;
  CLI::App* group = top.add_subcommand(name, description);
  group->require_subcommand(1);
  return group;
}

int standard_output_written() {
  // Output that never reached its destination (`> /dev/full`, a closed pipe) is a failed run.
  std::cout.flush();
  errno = 0;
  if (!std::cout || std::fflush(stdout) != 0 || std::ferror(stdout)) {
    const int err = errno;
    std::cerr << "fapcast: error: standard output: write failed"
              << (err != 0 ? std::string(": ") + std::strerror(err) : std::string()) << "\n";
    return kBadInput;
  }
  return kOk;
}

std::vector<AddCommand> registered_commands() {
  if (!registered_twice().empty())
    throw std::logic_error("command '" + registered_twice().front() + "' is registered twice");
  for (const auto& [name, add] : registry())
    if (std::find(kCommandOrder.begin(), kCommandOrder.end(), name) == kCommandOrder.end())
      throw std::logic_error("command '" + name + "' is not in kCommandOrder (cli/main.cpp)");
  std::vector<AddCommand> out;
  for (std::string_view name : kCommandOrder)
    if (const auto it = registry().find(name); it != registry().end()) out.push_back(it->second);
  return out;
}

}  // namespace fapcast::cli

int main(int argc, char** argv) {
  // Buffers of 1 MiB and more (a chunk's speech, a track's frames) straight from the kernel and
  // back: glibc's threshold otherwise rises to the largest buffer freed, and a long text's
  // chunk-by-chunk buffers then stay on the heap, so memory grows with the text
  // (spec/phones.md, "Memory"). No cost measured on a page (say_command_bench).
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
  // Heap memory freed at the top kept up to 8 MiB rather than 128 KiB: each piece of a track
  // allocates and frees the same few MB (frames, the search's trail), and memory given back is
  // faulted in again by the next piece (650 of a page's 5,900 page faults; peak RSS unchanged).
  mallopt(M_TRIM_THRESHOLD, 8 << 20);
  using namespace fapcast::cli;
  try {
    CLI::App app{"fapcast: speech to MPEG-4 facial animation (synthesis, .fap/FBA codec, RTP)"};
    app.require_subcommand(1);
    app.set_version_flag("--version", std::string("fapcast ") + FAPCAST_VERSION);
    for (const auto& add : registered_commands()) add(app);
    try {
      app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
      // --help and --version arrive here too, with exit code 0.
      if (app.exit(e) == 0) return standard_output_written();  // --help > /dev/full fails too
      for (const std::string& hint : unknown_option_hints(app, {argv + 1, argv + argc}))
        std::cerr << "fapcast: hint: " << hint << "\n";
      return kBadUsage;
    }
  } catch (...) {
    const ExitStatus status = exit_status(std::current_exception());
    std::cerr << status.message << "\n";
    return status.code;
  }
  return standard_output_written();
}
