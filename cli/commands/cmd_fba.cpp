// `fapcast encode IN.fap -o OUT.fba [--profile standard|fapcast] [--quant q] [--iperiod n | --archive]`
// and `fapcast decode IN.fba -o OUT.fap [--profile standard] [--player P]`: the binary MPEG-4 FBA
// stream (spec/fba.md). Argument parsing only; coding is encode_fba / decode_fba.
#include "command.hpp"
#include "fap_output.hpp"
#include "output_check.hpp"

#include "fapcast/codec/fap_text.hpp"
#include "fapcast/core/file_io.hpp"
#include "fapcast/fba/fba_file.hpp"

#include <filesystem>
#include <iostream>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>

namespace {
using namespace fapcast;

struct EncodeArgs {
  std::string in, out;
  std::string profile = "standard";
  int quant = -1;    // -1: the profile's default (standard 1, fapcast 0: lossless)
  int iperiod = 0;   // 0: the profile's default (standard 10 s, fapcast 20 s)
  bool archive = false;
};

struct DecodeArgs {
  std::string in, out;
  std::string profile;  // "standard": the standard syntax only
  std::string player;
};

FbaProfile profile_of(const std::string& name) { return name == "fapcast" ? FbaProfile::kFapcast : FbaProfile::kStandard; }

void encode(const EncodeArgs& a) {
  cli::check_output_writable(a.out);
  const FapTextRead r = read_fap_text(read_file(a.in), a.in);
  for (const auto& w : r.info.warnings) std::cerr << "fapcast: warning: " << w << "\n";
  const FbaProfile profile = profile_of(a.profile);
  const int quant = a.quant >= 0 ? a.quant : profile == FbaProfile::kStandard ? 1 : 0;
  FbaEncoderOptions options = a.archive ? fba_archive_options(profile, quant, r.sequence.rate) : FbaEncoderOptions{};
  options.profile = profile;
  options.fap_quant = quant;
  if (!a.archive) options.intra_period = a.iperiod;
  std::vector<std::uint8_t> bytes;
  FbaEncodeStats stats;
  try {
    bytes = encode_fba(r.sequence, options, &stats);
  } catch (const FbaEncodeError& e) {
    std::string hint;
    if (e.code() == fba_errc::uncodable_value && profile == FbaProfile::kStandard)
      hint = "; use --profile fapcast to code every value losslessly (standard FBA decoders refuse that profile)";
    throw std::runtime_error(a.in + ": " + e.what() + hint);
  }
  write_file_atomically(a.out, {reinterpret_cast<const char*>(bytes.data()), bytes.size()});
  std::cerr << "fapcast: " << a.out << ": " << r.sequence.frames.size() << " frames, " << bytes.size() << " bytes, "
            << fba_profile_name(profile) << " at fap_quant " << quant << (quant == 0 ? " (lossless)" : "") << ", "
            << stats.intra_planes << " intra planes\n";
  if (stats.not_read_alike > 0)
    std::cerr << "fapcast: note: " << a.out << ": " << stats.not_read_alike
              << " frames no coding of which every standard decoder reads alike (spec/fba.md §2): coded for the "
                 "reference reading, each followed by a start code\n";
}

void decode(const DecodeArgs& a) {
  cli::check_output_writable(a.out);
  const std::string bytes = read_file(a.in);
  FbaDecodeOptions options;
  options.standard_only = a.profile == "standard";
  FbaDecodeResult result =
      decode_fba(std::span(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()), options);
  const auto& report = result.report;
  for (const auto& e : report.errors) std::cerr << "fapcast: " << a.in << ": " << e.message() << "\n";
  if (report.frames_decoded == 0 && !report.ok()) throw std::runtime_error(a.in + ": no frame could be decoded");
  std::cerr << "fapcast: " << a.in << ": " << fba_profile_name(report.profile) << ", fap_quant " << report.fap_quant
            << (report.fap_quant == 0 ? " (lossless)" : "") << ", " << report.frames_decoded << " planes";
  if (report.profile == FbaProfile::kStandard && report.stuffing == FbaStuffing::kContinuous)
    std::cerr << " (stuffing read continuously: spec/fba.md §2)";
  if (!report.rate_known) std::cerr << ", no frame rate in the stream (25 fps assumed)";
  if (report.time_code_mismatches > 0) std::cerr << ", " << report.time_code_mismatches << " time codes off the frame count";
  std::cerr << "\n";
  if (!report.ok())
    std::cerr << "fapcast: " << a.in << ": " << report.frames_lost << " frames lost (held), " << report.errors_total
              << " errors\n";
  // .fba carries no name; the .fap header takes the file's stem.
  result.sequence.name = std::filesystem::path(a.out).stem().string();
  const FapTextWriteOptions fap = cli::fap_write_options(a.player);
  std::string text;
  try {
    text = write_fap_text(result.sequence, fap);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(a.out + ": " + e.what());
  }
  write_file_atomically(a.out, text);
  cli::print_notes(a.out, fap_text_player_notes(result.sequence, fap));
  if (!report.ok()) throw std::runtime_error(a.in + ": decoded with losses; " + a.out + " holds what survived");
}

const cli::Registration encode_command{"encode", [](CLI::App& app) {
  auto enc = std::make_shared<EncodeArgs>();
  auto* e = app.add_subcommand("encode", "Encode a .fap track as a binary MPEG-4 FBA stream (.fba)");
  e->add_option("IN", enc->in, "input .fap file")->required();
  e->add_option("-o,--output", enc->out, "output .fba file")->required();
  e->add_option("--profile", enc->profile,
                "standard (default: ISO/IEC 14496-2 FBA, read by every standard decoder) or fapcast (fapcast's own "
                "profile: every value losslessly, inter-FAP prediction; standard decoders refuse it)")
      ->check(CLI::IsMember({"standard", "fapcast"}))
      ->capture_default_str();
  e->add_option("--quant", enc->quant, "fap_quant 0 (lossless) .. 31; step = QP x quant (default: 1 standard, 0 fapcast)")
      ->check(CLI::Range(0, 31));
  auto* iperiod = e->add_option("--iperiod", enc->iperiod,
                                "an intra frame at least every this many frames (default: 10 s standard, 20 s fapcast)")
                      ->check(CLI::Range(1, 1 << 20));
  e->add_flag("--archive", enc->archive,
              "archival preset: an intra frame every " + std::to_string(kFbaArchiveIntraSeconds) +
                  " s (a corrupt byte or a seek costs up to that long)")
      ->excludes(iperiod);
  e->callback([enc] { encode(*enc); });
}};

const cli::Registration decode_command{"decode", [](CLI::App& app) {
  auto dec = std::make_shared<DecodeArgs>();
  auto* d = app.add_subcommand("decode", "Decode a binary MPEG-4 FBA stream (.fba, either profile) to a .fap track");
  d->add_option("IN", dec->in, "input .fba file")->required();
  d->add_option("-o,--output", dec->out, "output .fap file")->required();
  d->add_option("--profile", dec->profile, "standard: accept the standard syntax only (refuse a fapcast-profile stream)")
      ->check(CLI::IsMember({"standard"}));
  cli::add_player_option(d, dec->player);
  d->callback([dec] { decode(*dec); });
}};

}  // namespace
