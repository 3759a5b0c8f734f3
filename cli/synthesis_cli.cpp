#include "synthesis_cli.hpp"

#include "command.hpp"
#include "output_check.hpp"
#include "fapcast/render/mesh_export.hpp"
#include "default_voice.hpp"
#include "fap_output.hpp"
#include "file_extension.hpp"
#include "fapcast/utterance/voice_face.hpp"

#include "fapcast/codec/gltf_export.hpp"
#include "fapcast/face/face_model.hpp"
#include "fapcast/core/file_io.hpp"

#include <chrono>
#include <iostream>
#include <optional>
#include <sstream>

namespace fapcast::cli {

void add_synthesis_options(CLI::App& cmd, SynthesisOptions& options) {
  cmd.add_option("--beta", options.search.beta, "Weight of the join smoothness in the unit search's cost (>= 0; 0: fewest units)")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  cmd.add_option_function<std::size_t>(
         "--max-active",
         [&options](std::size_t n) { options.search.max_active = n > 0 ? std::optional<std::size_t>(n) : std::nullopt; },
         "Active states kept per phone in the unit search (0 = all)")
      ->default_str(std::to_string(options.search.max_active.value_or(0)));
  cmd.add_option("--duration-weight", options.search.duration_weight,
                 "Weight of the duration term in the unit search's cost: ln^2 of each phone's time warp (>= 0)")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  cmd.add_option("--context-weight", options.search.context_weight,
                 "Weight of the right-context term in the unit search's cost: a unit left where its recording "
                 "went on in another viseme class (>= 0)")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  cmd.add_option("--jaw-weight", options.search.jaw_weight,
                 "Weight of the jaw term in the unit search's cost: each unit's recorded jaw against the jaw its "
                 "phones want in context (>= 0)")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  cmd.add_option("--jaw-level", options.jaw_level,
                 "How much of the animation's slow jaw moves to the jaw its phones want in context, the lips' shape "
                 "held as far as the face allows (0: the units' own jaw, as recorded; 1: the wanted jaw)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd.add_option("--jaw-cutoff", options.jaw_cutoff_hz,
                 "How fast the wanted jaw may move, for the jaw term and the jaw's level (Hz, low-pass; 0.5-20: a jaw "
                 "moves below 10 Hz, and the filter needs less than half the 60 fps frame rate)")
      ->check(CLI::Range(0.5, 20.0))
      ->capture_default_str();
  cmd.add_flag_function(
      "--boundary-joins", [&options](std::int64_t) { options.concatenation.join_mid_phone = false; },
      options.concatenation.join_mid_phone
          ? "Hand over between units at phone boundaries (default: in the middle of the phone before)"
          : "Hand over between units at phone boundaries (the default)");
}

std::string synthesis_options_text(const SynthesisOptions& options) {
  const SynthesisOptions shipped;
  std::ostringstream text;
  if (options.search.beta != shipped.search.beta) text << " --beta " << options.search.beta;
  if (options.search.max_active != shipped.search.max_active)
    text << " --max-active " << options.search.max_active.value_or(0);
  if (options.search.duration_weight != shipped.search.duration_weight)
    text << " --duration-weight " << options.search.duration_weight;
  if (options.search.context_weight != shipped.search.context_weight)
    text << " --context-weight " << options.search.context_weight;
  if (options.search.jaw_weight != shipped.search.jaw_weight) text << " --jaw-weight " << options.search.jaw_weight;
  if (options.jaw_level != shipped.jaw_level) text << " --jaw-level " << options.jaw_level;
  if (options.jaw_cutoff_hz != shipped.jaw_cutoff_hz) text << " --jaw-cutoff " << options.jaw_cutoff_hz;
  if (options.concatenation.join_mid_phone != shipped.concatenation.join_mid_phone && !options.concatenation.join_mid_phone)
    text << " --boundary-joins";
  return text.str();
}

CLI::App* add_synthesis_command(CLI::App& app, const std::string& name, const std::string& description,
                                SynthesisArgs& args, std::function<void()> run) {
  CLI::App* cmd = app.add_subcommand(name, description);
  cmd->add_option("-o,--output", args.output,
                  "Animation file by extension, written atomically: .fap, .fba, .json, .bvh (FAPs) or .glb "
                  "(glTF mesh: the voice's PCA components as morph targets, its 60 fps PCA frames as weights); "
                  "with a rig (spec/rigs.md): .csv (Live Link Face, ARKit), .json with --rig (TalkingHead), "
                  ".vrma (VRM animation), .glb with --avatar; not needed with --cues-out alone");
  cmd->add_option("--voice", args.voice, "Voice file (default: the reference voice, built on first use)");
  CLI::Option* fps = cmd->add_option("--fps", args.fps, "Output frames per second (25, 30, 60; any 1..120); not .glb")
                         ->check(CLI::Range(1, 120))
                         ->capture_default_str();
  add_synthesis_options(*cmd, args.options);
  cmd->add_flag("--viseme", args.viseme, "Also write FAP 1 (the MPEG-4 viseme of each frame's phone); not .glb");
  cmd->add_option("--expression", args.expression_text,
                  "FAP 2 expression blended with the speech: NAME[:INTENSITY][,NAME[:INTENSITY]], names joy "
                  "sadness anger fear disgust surprise, intensity 0..63 (default 63)")
      ->check(CLI::Validator(
          [](const std::string& text) {
            try {
              parse_expression_blend(text);
              return std::string();
            } catch (const std::invalid_argument& e) {
              return std::string(e.what());
            }
          },
          "EXPRESSION"));
  cmd->add_option("--obj-frames-out", args.obj_frames, ".glb: also write every frame as OBJ (metres) into this folder, for debugging");
  add_player_option(cmd, args.player);
  cmd->add_option("--rig", args.rig.rig_text,
                  "Avatar rig: arkit (52 blendshapes), oculus (15 visemes), vrm (aa ih ou ee oh), vrm0 (A I U E O)");
  cmd->add_option("--avatar", args.rig.avatar, "A .glb avatar whose morph targets (ARKit or Oculus names) -o X.glb animates");
  cmd->add_option("--vmc", args.rig.vmc, "Also stream the rig live over VMC (OSC over UDP) to udp://HOST:PORT, in real time");
  add_cue_options(*cmd, args.cues);
  cmd->add_flag("-q,--quiet", args.quiet, "No progress on standard error");
  cmd->callback([&args, fps, name, run = std::move(run)] {
    if (!args.expression_text.empty()) args.expression = parse_expression_blend(args.expression_text);
    check_cue_args(name, args.cues);
    if (args.output.empty()) {
      if (args.cues.output.empty()) throw UsageError(name + ": -o OUT is required (or --cues-out FILE for mouth cues alone)");
      if (!args.voice.empty() || fps->count() > 0 || args.viseme || args.expression || !args.obj_frames.empty() ||
          !args.player.empty() || !args.rig.rig_text.empty() || !args.rig.avatar.empty() || !args.rig.vmc.empty())
        throw UsageError(name + ": --voice, --fps, --viseme, --expression, --obj-frames-out, --player, --rig, --avatar "
                         "and --vmc shape the animation: give it with -o OUT");
      check_output_writable(args.cues.output);  // before the speech is made or aligned
      run();
      return;
    }
    if (!is_animation_output(args.output) && !is_rig_output(args.output, args.rig))
      throw UsageError(name + ": output '" + args.output + "' must end in .fap, .fba, .json, .bvh, .glb, .csv or .vrma");
    args.fps_given = fps->count() > 0;
    check_rig_args(name, args.output, args.rig);
    if (is_rig_output(args.output, args.rig)) {
      if (args.fps_given && args.fps != Voice::kFramesPerSecond)
        throw UsageError(name + ": rig tracks hold the voice's " + std::to_string(Voice::kFramesPerSecond) +
                         " fps frames; --fps does not apply");
      if (args.viseme) throw UsageError(name + ": --viseme (FAP 1) has no place in a rig track");
      if (!args.obj_frames.empty()) throw UsageError(name + ": --obj-frames-out needs the voice's own .glb (no --avatar)");
      if (args.expression) throw UsageError(name + ": --expression is not fitted into rig tracks yet");
    }
    if (is_mesh_output(args.output) && args.fps_given && args.fps != Voice::kFramesPerSecond)
      throw UsageError(name + ": a .glb holds the voice's " + std::to_string(Voice::kFramesPerSecond) +
                       " fps PCA frames as keyframes (players interpolate); --fps does not apply");
    if (is_mesh_output(args.output) && args.viseme)
      throw UsageError(name + ": --viseme (FAP 1) has no place in a .glb");
    if (!is_mesh_output(args.output) && !args.obj_frames.empty())
      throw UsageError(name + ": --obj-frames-out needs a .glb output");
    if (!args.player.empty() && lower_extension(args.output) != ".fap")
      throw UsageError(name + ": --player applies to a .fap output");
    check_output_writable(args.output);  // before the voice is read and the speech synthesized
    check_output_writable(args.cues.output);
    run();
  });
  return cmd;
}

namespace {

// The voice's PCA frames (with the expression's weight) as a morph animation at the voice's
// 60 fps: the frames shown while the audio plays, on the ICT face's triangles.
MorphAnimation mesh_animation(const SynthesisArgs& args, const SpeechBasis& basis,
                                     const SynthesizedTrack& track, std::int64_t audio_samples,
                                     const std::string& name) {
  const FrameRate rate{static_cast<std::uint32_t>(Voice::kFramesPerSecond), 1};
  Eigen::MatrixXf weights = speech_weights(track.pca_frames, basis);
  const auto shown = frames_shown(audio_samples, rate, track.timeline.sample_rate);
  if (weights.rows() > shown) weights.conservativeResize(shown, Eigen::NoChange);
  const FaceModel& face = ict_face_model();
  if (basis.dimension() != 3 * static_cast<Eigen::Index>(face.vertex_count()))
    throw std::runtime_error(args.output + ": the voice's face has " + std::to_string(basis.dimension() / 3) +
                             " vertices, not the ICT face's " + std::to_string(face.vertex_count()) +
                             ": no faces to write a mesh with");
  return morph_animation_from_speech(basis, face.faces, std::move(weights), rate, name);
}

}  // namespace

Voice open_synthesis_voice(const SynthesisArgs& args) {
  Voice voice = open_voice_or_default(args.voice, args.quiet);
  check_voice_phone_set(voice, synthesis_voice_name(args));
  return voice;
}

std::string synthesis_voice_name(const SynthesisArgs& args) {
  return args.voice.empty() ? std::string("the default voice") : args.voice;
}

AnimationOptions animation_options(const SynthesisArgs& args, std::string name) {
  AnimationOptions animation;
  animation.rate = {static_cast<std::uint32_t>(args.fps), 1};
  animation.viseme = args.viseme;
  animation.name = std::move(name);
  if (args.expression) animation.expression = expression_field(*args.expression);
  return animation;
}

std::string synthesis_summary(const SynthesisArgs& args, const SynthesisReport& report, std::string_view outputs) {
  std::ostringstream line;
  line << args.output << ": " << report.frames << " frames at " << report.fps << " fps (" << report.audio_seconds
       << " s), " << report.phones << " phones in " << report.units << " units";
  if (report.pieces > 1) line << " (" << report.pieces << " pieces cut in pauses)";
  line << ", synthesised in " << report.synthesis_ms << " ms";
  if (args.expression) line << ", expression " << expression_blend_text(*args.expression);
  line << outputs;
  if (report.substituted > 0) line << "; " << report.substituted << " phones borrowed a nearby viseme class";
  if (report.dropped > 0) line << "; " << report.dropped << " phones shorter than a frame dropped";
  return line.str();
}

void synthesize_to_file(const SynthesisArgs& args, std::span<const TimedPhone> phones,
                        SampleRate sample_rate, std::int64_t audio_samples,
                        const std::string& source, const std::string& name) {
  const std::string cue_summary = write_cue_output(args.cues, phones, sample_rate, audio_samples);
  if (args.output.empty()) {
    std::cout << args.cues.output << ": " << static_cast<double>(audio_samples) / static_cast<double>(sample_rate.hz)
              << " s, " << phones.size() << " phones" << cue_summary << "\n";
    return;
  }
  const Voice voice = open_synthesis_voice(args);
  const SpeechBasis speech = speech_basis(voice, args.expression);
  const SynthesisOptions& options = args.options;
  const auto start = std::chrono::steady_clock::now();
  SynthesizedTrack track = synthesize(voice, phones, sample_rate, audio_samples, options, source);
  std::size_t frames = 0;
  int fps = args.fps;
  double seconds = 0;
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  std::string rig_summary;
  if (is_rig_output(args.output, args.rig)) {
    rig_summary = write_rig_outputs(args.rig, args.output, voice, track, audio_samples, true, args.words);
    seconds = elapsed();
    frames = static_cast<std::size_t>(std::min<std::int64_t>(
        frames_shown(audio_samples, {static_cast<std::uint32_t>(Voice::kFramesPerSecond), 1}, sample_rate),
        track.pca_frames.rows()));
    fps = Voice::kFramesPerSecond;
  } else if (is_mesh_output(args.output)) {
    const MorphAnimation animation = mesh_animation(args, speech, track, audio_samples, name);
    seconds = elapsed();
    write_file_atomically(args.output, write_glb(animation));
    if (!args.obj_frames.empty())
      std::cout << args.obj_frames << ": " << write_obj_frames(animation, args.obj_frames) << " OBJ frames\n";
    frames = static_cast<std::size_t>(animation.weights.rows());
    fps = Voice::kFramesPerSecond;
  } else {
    const FeaturePointBasis basis = face_basis(speech, voice, synthesis_voice_name(args));
    const AnimationOptions animation = animation_options(args, name);
    track.pca_frames = speech_weights(track.pca_frames, speech);
    const FapSequence seq = fap_track(track, basis, animation, audio_samples);
    seconds = elapsed();
    write_animation(args.output, seq, fap_write_options(args.player), sample_rate, basis.neutral);
    frames = seq.frames.size();
  }
  if (rig_summary.empty() && !args.rig.vmc.empty())
    rig_summary = write_rig_outputs(args.rig, args.output, voice, track, audio_samples, false, args.words);
  SynthesisReport report;
  report.frames = frames;
  report.fps = fps;
  report.audio_seconds = static_cast<double>(audio_samples) / static_cast<double>(sample_rate.hz);
  report.phones = track.timeline.phones.size();
  report.units = track.search.units.size();
  report.synthesis_ms = seconds * 1000.0;
  report.substituted = track.substituted;
  report.dropped = track.timeline.dropped;
  std::cout << synthesis_summary(args, report, rig_summary + cue_summary) << "\n";
}

}  // namespace fapcast::cli
