#include "synthesis_cli.hpp"

#include "command.hpp"
#include "fapcast/render/mesh_export.hpp"
#include "default_voice.hpp"
#include "fapcast/utterance/voice_face.hpp"

#include "fapcast/codec/gltf_export.hpp"
#include "fapcast/face/face_model.hpp"
#include "fapcast/core/file_io.hpp"

#include <chrono>
#include <iostream>

namespace fapcast::cli {

CLI::App* add_synthesis_command(CLI::App& app, const std::string& name, const std::string& description,
                                SynthesisArgs& args, std::function<void()> run) {
  CLI::App* cmd = app.add_subcommand(name, description);
  cmd->add_option("-o,--output", args.output,
                  "Animation file by extension, written atomically: .fap, .fba, .json, .bvh (FAPs) or .glb "
                  "(glTF mesh: the voice's PCA components as morph targets, its 60 fps PCA frames as weights)")
      ->required();
  cmd->add_option("--voice", args.voice, "Voice file (default: the reference voice, built on first use)");
  CLI::Option* fps = cmd->add_option("--fps", args.fps, "Output frames per second (25, 30, 60; any 1..120); not .glb")
                         ->check(CLI::Range(1, 120))
                         ->capture_default_str();
  cmd->add_option("--beta", args.beta, "Weight of the junction smoothness in the unit search (>= 0)")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  cmd->add_option("--max-active", args.max_active, "Active states kept per phone (0 = all)")
      ->capture_default_str();
  cmd->add_option("--duration-weight", args.duration_weight,
                  "Weight of the duration term in the unit search: ln^2 of each phone's time warp (>= 0)")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  cmd->add_flag("--boundary-joins", args.boundary_joins,
                "Hand over between units at phone boundaries (default: in the middle of the phone before)");
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
  cmd->add_option("--obj-frames", args.obj_frames, ".glb: also write every frame as OBJ (metres) here, for debugging");
  cmd->add_flag("-q,--quiet", args.quiet, "No progress on standard error");
  cmd->callback([&args, fps, name, run = std::move(run)] {
    if (!is_animation_output(args.output))
      throw UsageError(name + ": output '" + args.output + "' must end in .fap, .fba, .json, .bvh or .glb");
    args.fps_given = fps->count() > 0;
    if (is_mesh_output(args.output) && args.fps_given && args.fps != Voice::kFramesPerSecond)
      throw UsageError(name + ": a .glb holds the voice's " + std::to_string(Voice::kFramesPerSecond) +
                       " fps PCA frames as keyframes (players interpolate); --fps does not apply");
    if (is_mesh_output(args.output) && args.viseme)
      throw UsageError(name + ": --viseme (FAP 1) has no place in a .glb");
    if (!is_mesh_output(args.output) && !args.obj_frames.empty())
      throw UsageError(name + ": --obj-frames needs a .glb output");
    if (!args.expression_text.empty()) args.expression = parse_expression_blend(args.expression_text);
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
  const auto shown = frames_shown(audio_samples, rate, track.timeline.sample_rate_hz);
  if (weights.rows() > shown) weights.conservativeResize(shown, Eigen::NoChange);
  const FaceModel& face = ict_face_model();
  if (basis.mean.cols() != 3 * static_cast<Eigen::Index>(face.vertex_count()))
    throw std::runtime_error(args.output + ": the voice's face has " + std::to_string(basis.mean.cols() / 3) +
                             " vertices, not the ICT face's " + std::to_string(face.vertex_count()) +
                             ": no faces to write a mesh with");
  return morph_animation_from_speech(basis, face.faces, std::move(weights), rate, name);
}

}  // namespace

void synthesize_to_file(const SynthesisArgs& args, std::span<const TimedPhone> phones,
                        std::int64_t sample_rate_hz, std::int64_t audio_samples,
                        const std::string& source, const std::string& name) {
  const Voice voice = open_voice_or_default(args.voice, args.quiet);
  const std::string voice_name = args.voice.empty() ? std::string("the default voice") : args.voice;
  check_voice_phone_set(voice, voice_name);
  const SpeechBasis speech = speech_basis(voice, args.expression);
  SynthesisOptions options;
  options.search.beta = args.beta;
  if (args.max_active > 0) options.search.max_active = args.max_active;
  options.search.duration_weight = args.duration_weight;
  options.concatenation.join_mid_phone = !args.boundary_joins;
  const auto start = std::chrono::steady_clock::now();
  SynthesizedTrack track = synthesize(voice.graph(), voice.frame_coefficients(), phones,
                                                    sample_rate_hz, audio_samples, options, source);
  std::size_t frames = 0;
  int fps = args.fps;
  double seconds = 0;
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  if (is_mesh_output(args.output)) {
    const MorphAnimation animation = mesh_animation(args, speech, track, audio_samples, name);
    seconds = elapsed();
    write_file_atomically(args.output, write_glb(animation));
    if (!args.obj_frames.empty())
      std::cout << args.obj_frames << ": " << write_obj_frames(animation, args.obj_frames) << " OBJ frames\n";
    frames = static_cast<std::size_t>(animation.weights.rows());
    fps = Voice::kFramesPerSecond;
  } else {
    const FeaturePointBasis basis = face_basis(speech, voice, voice_name);
    AnimationOptions animation;
    animation.rate = {static_cast<std::uint32_t>(args.fps), 1};
    animation.viseme = args.viseme;
    animation.name = name;
    if (args.expression) animation.expression = expression_field(*args.expression);
    track.pca_frames = speech_weights(track.pca_frames, speech);
    const FapSequence seq = fap_track(track, basis, animation, audio_samples);
    seconds = elapsed();
    write_animation(args.output, seq, sample_rate_hz, basis.neutral);
    frames = seq.frames.size();
  }
  std::cout << args.output << ": " << frames << " frames at " << fps << " fps ("
            << static_cast<double>(audio_samples) / static_cast<double>(sample_rate_hz) << " s), "
            << track.timeline.phones.size() << " phones in " << track.search.units.size()
            << " units, synthesised in " << seconds * 1000.0 << " ms";
  if (args.expression) std::cout << ", expression " << expression_blend_text(*args.expression);
  if (track.substituted > 0) std::cout << "; " << track.substituted << " phones borrowed a nearby viseme class";
  if (track.timeline.dropped > 0) std::cout << "; " << track.timeline.dropped << " phones shorter than a frame dropped";
  std::cout << "\n";
}

}  // namespace fapcast::cli
