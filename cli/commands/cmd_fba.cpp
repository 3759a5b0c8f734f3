// `fapcast encode IN.fap -o OUT.fba [--quant q] [--iperiod n | --archive]` and
// `fapcast decode IN.fba -o OUT.fap`: the binary MPEG-4 FBA stream (spec/fba.md).
// Argument parsing only; coding is encode_fba / decode_fba.
#include "command.hpp"

#include "fapcast/codec/fap_text.hpp"
#include "fapcast/fba/fba_file.hpp"
#include "fapcast/core/file_io.hpp"

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
  int quant = FbaEncoderOptions{}.fap_quant;
  int iperiod = FbaEncoderOptions{}.intra_period;
  bool archive = false;
};

struct DecodeArgs {
  std::string in, out;
};

void encode(const EncodeArgs& a) {
  const FapTextRead r = read_fap_text(read_file(a.in), a.in);
  for (const auto& w : r.info.warnings) std::cerr << "fapcast: warning: " << w << "\n";
  std::vector<std::uint8_t> bytes;
  try {
    const FbaEncoderOptions options =
        a.archive ? fba_archive_options(a.quant, r.sequence.rate) : FbaEncoderOptions{a.quant, a.iperiod};
    bytes = encode_fba(r.sequence, options);
  } catch (const FbaEncodeError& e) {
    throw std::runtime_error(a.in + ": " + e.what());
  }
  write_file_atomically(a.out, {reinterpret_cast<const char*>(bytes.data()), bytes.size()});
  std::cerr << "fapcast: " << a.out << ": " << r.sequence.frames.size() << " frames, " << bytes.size()
            << " bytes\n";
}

void decode(const DecodeArgs& a) {
  const std::string bytes = read_file(a.in);
  FbaDecodeResult result = decode_fba(
      std::span(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()));
  const auto& report = result.report;
  for (const auto& e : report.errors) std::cerr << "fapcast: " << a.in << ": " << e.message() << "\n";
  if (report.frames_decoded == 0 && !report.ok())
    throw std::runtime_error(a.in + ": no frame could be decoded");
  if (!report.ok())
    std::cerr << "fapcast: " << a.in << ": " << report.frames_lost << " frames lost (held), "
              << report.errors_total << " errors\n";
  // .fba carries no name; the .fap header takes the file's stem.
  result.sequence.name = std::filesystem::path(a.out).stem().string();
  write_file_atomically(a.out, write_fap_text(result.sequence));
  if (!report.ok()) throw std::runtime_error(a.in + ": decoded with losses; " + a.out + " holds what survived");
}

const cli::Registration reg{"encode", [](CLI::App& app) {
  auto enc = std::make_shared<EncodeArgs>();
  auto* e = app.add_subcommand("encode", "Encode a .fap track as a binary MPEG-4 FBA stream (.fba)");
  e->add_option("IN", enc->in, "input .fap file")->required();
  e->add_option("-o,--output", enc->out, "output .fba file")->required();
  e->add_option("--quant", enc->quant, "fap_quant 0 (lossless) .. 31; step = QP x quant")
      ->check(CLI::Range(0, 31))->capture_default_str();
  auto* iperiod = e->add_option("--iperiod", enc->iperiod, "an intra frame at least every this many frames")
                      ->check(CLI::Range(1, 1 << 20))->capture_default_str();
  e->add_flag("--archive", enc->archive,
              "archival preset: an intra frame every " + std::to_string(kFbaArchiveIntraSeconds) +
                  " s (about a third smaller; a corrupt byte or a seek costs up to that long)")
      ->excludes(iperiod);
  e->callback([enc] { encode(*enc); });
}};

const cli::Registration decode_reg{"decode", [](CLI::App& app) {
  auto dec = std::make_shared<DecodeArgs>();
  auto* d = app.add_subcommand("decode", "Decode a binary MPEG-4 FBA stream (.fba) to a .fap track");
  d->add_option("IN", dec->in, "input .fba file")->required();
  d->add_option("-o,--output", dec->out, "output .fap file")->required();
  d->callback([dec] { decode(*dec); });
}};

}  // namespace
