// `fapcast fap info FILE [--json]` and `fapcast fap convert IN -o OUT [--dialect strict|69 | --player P]`:
// inspect and convert .fap text files (spec/fap-text.md). Argument parsing and printing only;
// reading, writing and statistics are codec functions.
#include "command.hpp"
#include "output_check.hpp"
#include "fap_output.hpp"

#include "fapcast/codec/fap_stats.hpp"
#include "fapcast/codec/fap_table.hpp"
#include "fapcast/codec/fap_text.hpp"
#include "fapcast/fba/fba_file.hpp"
#include "fapcast/core/file_io.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <iostream>
#include <memory>
#include <string>

namespace {
using namespace fapcast;

// What the file format contributed besides the frames; a later FBA reader fills its own.
struct SourceSummary {
  std::string format;          // "fap-text"
  std::string version;         // "2.1"
  std::string layout;          // "68-token masks, CRLF"
  std::uint64_t header_frames = 0;
};

FapTextRead read_fap_file(const std::string& path) {
  const FapTextRead r = read_fap_text(read_file(path), path);
  for (const auto& w : r.info.warnings) std::cerr << "fapcast: warning: " << w << "\n";
  return r;
}

std::string seconds(std::int64_t ms) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%lld.%03lld s", static_cast<long long>(ms / 1000),
                static_cast<long long>(ms % 1000));
  return buf;
}

void print_text(std::ostream& out, const std::string& path, const std::string& name,
                const SourceSummary& src, const FapStats& s) {
  out << "file:      " << path << "\n"
      << "format:    " << src.format << " " << src.version << " (" << src.layout << ")\n"
      << "name:      " << name << "\n"
      << "fps:       " << fap_text_fps(s.rate) << " (exactly " << s.rate.numerator << "/"
      << s.rate.denominator << ")\n"
      << "frames:    " << s.frame_count << " (header: " << src.header_frames << ")\n"
      << "duration:  " << seconds(s.duration_ms) << "\n"
      << "masked:    " << s.masked_faps.size() << " FAPs\n";
  char row[128];
  std::snprintf(row, sizeof row, "  %3s  %-22s %8s %8s %8s\n", "FAP", "name", "frames", "min",
                "max");
  out << row;
  for (const auto& r : s.masked_faps) {
    std::snprintf(row, sizeof row, "  %3d  %-22s %8llu %8d %8d\n", r.fap,
                  std::string(fap_info(r.fap).name).c_str(),
                  static_cast<unsigned long long>(r.frames_masked), r.min, r.max);
    out << row;
  }
}

nlohmann::json to_json(const std::string& path, const std::string& name, const SourceSummary& src,
                       const FapStats& s, const std::vector<std::string>& warnings) {
  nlohmann::json faps = nlohmann::json::array();
  for (const auto& r : s.masked_faps)
    faps.push_back({{"fap", r.fap},
                    {"name", fap_info(r.fap).name},
                    {"frames", r.frames_masked},
                    {"min", r.min},
                    {"max", r.max}});
  auto set_bits = [](const auto& bits) {
    nlohmann::json a = nlohmann::json::array();
    for (std::size_t i = 0; i < bits.size(); ++i)
      if (bits.test(i)) a.push_back(i);
    return a;
  };
  return {{"file", path},
          {"format", src.format},
          {"version", src.version},
          {"layout", src.layout},
          {"name", name},
          {"fps", fap_text_fps(s.rate)},
          {"rate", {{"numerator", s.rate.numerator}, {"denominator", s.rate.denominator}}},
          {"frames", s.frame_count},
          {"header_frames", src.header_frames},
          {"duration_ms", s.duration_ms},
          {"faps", faps},
          {"visemes_used", set_bits(s.visemes_used)},
          {"expressions_used", set_bits(s.expressions_used)},
          {"warnings", warnings}};
}

// A binary FBA stream (spec/fba.md) read as a text file would be: frames plus a summary.
FapTextRead read_fba_file(const std::string& path, const std::string& bytes, SourceSummary& src) {
  FbaDecodeResult d = decode_fba(
      std::span(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()));
  FapTextRead r;
  r.sequence = std::move(d.sequence);
  r.sequence.name = std::filesystem::path(path).stem().string();  // .fba carries no name
  // A corrupt or truncated stream is bad input, not a summary with warnings: its first error.
  if (!d.report.ok())
    throw std::runtime_error(path + ": " + (d.report.errors.empty() ? std::string("fba: corrupt stream")
                                                                    : d.report.errors.front().message()) +
                             " (" + std::to_string(d.report.errors_total) + " errors, " +
                             std::to_string(d.report.frames_lost) + " frames lost)");
  src = {"fba", fba_profile_name(d.report.profile), std::to_string(d.report.frames_lost) + " frames lost, " +
                                  std::to_string(d.report.bytes) + " bytes",
         d.report.frames_decoded + d.report.frames_lost + d.report.frames_skipped};
  return r;
}

void info(const std::string& path, bool json) {
  const std::string bytes = read_file(path);
  SourceSummary src;
  FapTextRead r;
  // An FBA stream by its start-code prefix or its extension (a corrupt first start code is still
  // an FBA stream, reported as one, not as "not a text file").
  const bool fba = fba_file_profile({reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()}) ||
                   bytes.starts_with(std::string_view("\0\0\1", 3)) ||
                   std::filesystem::path(path).extension() == ".fba";
  if (fba) {
    r = read_fba_file(path, bytes, src);
  } else {
    r = read_fap_text(bytes, path);
    for (const auto& w : r.info.warnings) std::cerr << "fapcast: warning: " << w << "\n";
    src = {"fap-text", r.info.version, r.info.describe(), r.info.header_frame_count};
  }
  const FapStats stats = fap_stats(r.sequence);
  if (json)
    // The reader repairs names that are not UTF-8; a path may still not be: replace, not throw.
    std::cout << to_json(path, r.sequence.name, src, stats, r.info.warnings)
                     .dump(2, ' ', false, nlohmann::json::error_handler_t::replace)
              << "\n";
  else
    print_text(std::cout, path, r.sequence.name, src, stats);
}

void convert(const std::string& in, const std::string& out, const std::string& dialect, const std::string& player) {
  cli::check_output_writable(out);
  const FapTextRead r = read_fap_file(in);
  const auto d = dialect == "69" ? FapTextDialect::kMask69 : FapTextDialect::kStrict;
  const FapTextWriteOptions options = cli::fap_write_options(player, d);
  if (d == FapTextDialect::kMask69) {
    if (const auto lossy = mask69_lossy_frames(r.sequence); lossy > 0)
      std::cerr << "fapcast: warning: " << in << ": " << lossy
                << " frames have FAP 1/2 fields the 69-token dialect cannot carry; only "
                   "viseme_select1 and expression_select1 are kept\n";
  }
  std::string text;
  try {
    text = write_fap_text(r.sequence, options);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(out + ": " + e.what());
  }
  write_file_atomically(out, text);
  std::cout << "wrote " << out << ": " << r.sequence.frames.size() << " frames, "
            << (player.empty() ? (d == FapTextDialect::kMask69 ? "69-token dialect" : "strict dialect") : "for " + player)
            << "\n";
  if (d != FapTextDialect::kMask69) cli::print_notes(out, fap_text_player_notes(r.sequence, options));
}

const cli::Registration fap_command{"fap", [](CLI::App& app) {
  auto* fap = app.add_subcommand("fap", "Inspect and convert .fap text files");
  fap->require_subcommand(1);

  auto* info_cmd = fap->add_subcommand(
      "info", "Version, dialect, fps, frames, duration, masked FAPs with min/max (.fap or .fba)");
  auto info_path = std::make_shared<std::string>();
  auto as_json = std::make_shared<bool>(false);
  info_cmd->add_option("FILE", *info_path, ".fap or .fba file")->required();
  info_cmd->add_flag("--json", *as_json, "Machine-readable output");
  info_cmd->callback([=] { info(*info_path, *as_json); });

  auto* conv = fap->add_subcommand("convert", "Rewrite a .fap file in the strict or 69-token dialect");
  auto in = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  auto dialect = std::make_shared<std::string>("strict");
  auto player = std::make_shared<std::string>();
  conv->add_option("IN", *in, "input .fap file")->required();
  conv->add_option("-o,--output", *out, "output .fap file (written atomically)")->required();
  auto* dialect_option = conv->add_option("--dialect", *dialect, "strict (default) or 69 (Greta's own exporter)")
                             ->check(CLI::IsMember({"strict", "69"}));
  cli::add_player_option(conv, *player)->excludes(dialect_option);
  conv->callback([=] { convert(*in, *out, *dialect, *player); });
}};

}  // namespace
