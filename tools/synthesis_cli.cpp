#include "synthesis_cli.hpp"

#include "command.hpp"
#include "voice_face.hpp"

#include <chrono>
#include <iostream>

namespace fapcast::tools {

void add_synthesis_options(CLI::App* cmd, SynthesisArgs& args) {
  cmd->add_option("-o,--output", args.output,
                  "Animation file: .fap, .fba, .json or .bvh (by extension; written atomically)")
      ->required();
  cmd->add_option("--voice", args.voice, "Voice file (default: the reference voice, built on first use)");
  cmd->add_option("--fps", args.fps, "Output frames per second (25, 30, 60; any 1..120)")
      ->check(CLI::Range(1, 120))
      ->capture_default_str();
  cmd->add_option("--beta", args.beta, "Weight of the junction smoothness in the unit search (>= 0)")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  cmd->add_option("--max-active", args.max_active, "Active states kept per phone (0 = all)")
      ->capture_default_str();
  cmd->add_flag("--viseme", args.viseme, "Also write FAP 1 (the MPEG-4 viseme of each frame's phone)");
  cmd->add_flag("-q,--quiet", args.quiet, "No progress on standard error");
}

void check_animation_output(const std::string& command, const SynthesisArgs& args) {
  if (!is_animation_output(args.output))
    throw UsageError(command + ": output '" + args.output + "' must end in .fap, .fba, .json or .bvh");
}

void synthesize_to_file(const SynthesisArgs& args, std::span<const synth::TimedPhone> phones,
                        std::int64_t sample_rate_hz, std::int64_t audio_samples,
                        const std::string& source, const std::string& name) {
  const synth::Voice voice = open_voice_or_default(args.voice, args.quiet);
  const std::string voice_name = args.voice.empty() ? std::string("the default voice") : args.voice;
  check_voice_phone_set(voice, voice_name);
  const codec::FeaturePointBasis basis = face_basis(voice, voice_name);
  synth::SynthesisOptions options;
  options.search.beta = args.beta;
  if (args.max_active > 0) options.search.max_active = args.max_active;
  const auto start = std::chrono::steady_clock::now();
  const synth::SynthesizedTrack track = synth::synthesize(voice.graph(), voice.frame_coefficients(), phones,
                                                          sample_rate_hz, audio_samples, options, source);
  AnimationOptions animation;
  animation.rate = {static_cast<std::uint32_t>(args.fps), 1};
  animation.viseme = args.viseme;
  animation.name = name;
  const codec::FapSequence seq = fap_track(track, basis, animation, audio_samples);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_animation(args.output, seq, sample_rate_hz, basis.neutral);
  std::cout << args.output << ": " << seq.frames.size() << " frames at " << args.fps << " fps ("
            << static_cast<double>(audio_samples) / static_cast<double>(sample_rate_hz) << " s), "
            << track.timeline.phones.size() << " phones in " << track.search.units.size()
            << " units, synthesised in " << seconds * 1000.0 << " ms";
  if (track.substituted > 0) std::cout << "; " << track.substituted << " phones borrowed a nearby viseme class";
  if (track.timeline.dropped > 0) std::cout << "; " << track.timeline.dropped << " phones shorter than a frame dropped";
  std::cout << "\n";
}

}  // namespace fapcast::tools
