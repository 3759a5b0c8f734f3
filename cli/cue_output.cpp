#include "cue_output.hpp"

#include "command.hpp"

#include "fapcast/core/file_io.hpp"
#include "fapcast/cues/mouth_cues.hpp"

#include <filesystem>

namespace fapcast::cli {

void add_cue_options(CLI::App& command, CueArgs& args) {
  command.add_option("--cues-out", args.output,
                     "Also write 2D mouth cues (shapes A-H, X) in Rhubarb Lip Sync's format by extension: .tsv, "
                     ".xml or .json (spec/mouth-cues.md); alone, without -o, only the cues are made");
  command.add_option("--cues-format", args.format_name, "The cues' format whatever the extension: tsv, xml or json")
      ->check(CLI::IsMember({"tsv", "xml", "json"}));
  command.add_option("--extended-shapes", args.extended,
                     "The extended mouth shapes the drawings have, as Rhubarb's --extendedShapes: any of G, H, X "
                     "(\"\" for the six basic shapes only)")
      ->check(CLI::Validator(
          [](const std::string& text) {
            return drawn_shapes(text) ? std::string()
                                      : "'" + text + "' must be G, H and X, each at most once, in any order";
          },
          "SHAPES"))
      ->capture_default_str();
}

void check_cue_args(const std::string& command, CueArgs& args) {
  if (args.output.empty()) {
    if (!args.format_name.empty()) throw UsageError(command + ": --cues-format applies to a --cues-out file");
    return;
  }
  args.format = args.format_name.empty() ? rhubarb_format_from_path(args.output)
                                         : rhubarb_format_from_name(args.format_name);
  if (!args.format)
    throw UsageError(command + ": --cues-out '" + args.output +
                     "' must end in .tsv, .xml or .json, or name its format with --cues-format");
}

std::string write_cue_output(const CueArgs& args, std::span<const TimedPhone> phones, SampleRate rate,
                             std::int64_t audio_samples) {
  if (args.output.empty()) return {};
  MouthCueOptions options;
  options.drawn = *drawn_shapes(args.extended);  // checked by the option's validator
  RhubarbResult result;
  result.cues = mouth_cues(phones, rate, audio_samples, options);
  result.duration = truncated_centiseconds(audio_samples, rate);
  result.drawn = options.drawn;
  // Rhubarb's metadata holds the recording's full path.
  if (!args.sound_file.empty()) result.sound_file = std::filesystem::absolute(args.sound_file).string();
  write_file_atomically(args.output, write_rhubarb(result, *args.format));
  return "; " + std::to_string(result.cues.size()) + " mouth cues in " + args.output;
}

}  // namespace fapcast::cli
