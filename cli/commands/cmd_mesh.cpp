// Mesh commands (spec/adaptation.md, spec/gltf.md):
//   fapcast adapt TARGETS_DIR GENERIC.obj SPECIFIC.obj -o DIR
//   fapcast expressions -o DIR | OUT.glb [--intensity N] [--fps N] [--seconds S] [--obj-frames-out DIR]
//   fapcast render IN.glb -o DIR [--view face|mouth] [--width PX] [--every N]
// Argument parsing only; synth adapts and builds expressions, codec writes and reads glTF, the
// rasteriser (render/rasteriser) draws.
#include "animation.hpp"
#include "command.hpp"
#include "output_check.hpp"
#include "fapcast/render/mesh_export.hpp"
#include "fapcast/render/rasteriser.hpp"

#include "fapcast/codec/gltf_export.hpp"
#include "fapcast/face/face_model.hpp"
#include "fapcast/face/facial_expression.hpp"
#include "fapcast/face/obj_targets.hpp"
#include "fapcast/core/file_io.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <numbers>

namespace {
using namespace fapcast;
namespace fs = std::filesystem;

WriteFile write_into(const fs::path& dir) {
  fs::create_directories(dir);
  return [dir](const std::string& name, std::string_view bytes) {
    write_file_atomically(dir / name, bytes);
  };
}

const cli::Registration mesh_adapt_command{"adapt", [](CLI::App& app) {
  struct Args {
    std::string generic, specific, targets, output;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = app.add_subcommand(
      "adapt", "Adapt morph targets (OBJ meshes with the generic face's topology) from a generic "
               "face to a specific one: per-vertex area-weighted triangle maps (spec/adaptation.md)");
  cmd->add_option("TARGETS", args->targets, "Folder of target meshes (*.obj) on the generic face")->required();
  cmd->add_option("GENERIC", args->generic, "Generic neutral mesh (.obj)")->required();
  cmd->add_option("SPECIFIC", args->specific, "Specific neutral mesh (.obj), same topology")->required();
  cmd->add_option("-o,--output", args->output, "Output folder (created; files written atomically)")
      ->required();
  cmd->callback([args] {
    std::error_code ec;
    if (fs::exists(args->output, ec) && fs::equivalent(args->output, args->targets, ec))
      throw cli::UsageError("adapt: the output folder must not be the targets folder");
    const auto count = adapt_obj_targets(args->generic, args->specific, args->targets,
                                                write_into(args->output));
    std::cout << "adapt: " << count << " targets -> " << args->output << "\n";
  });
}};

// Each of the six expressions rises and falls in turn (half a sine over `seconds` each).
Eigen::MatrixXf expression_tour(int fps, double seconds) {
  const int per = std::max(2, static_cast<int>(std::lround(fps * seconds)));
  const auto k = static_cast<Eigen::Index>(kExpressionCount);
  Eigen::MatrixXf w = Eigen::MatrixXf::Zero(per * k + 1, k);
  for (Eigen::Index e = 0; e < k; ++e)
    for (int f = 0; f <= per; ++f)
      w(e * per + f, e) = static_cast<float>(std::sin(std::numbers::pi * f / per));
  return w;
}

const cli::Registration expressions_command{"expressions", [](CLI::App& app) {
  struct Args {
    std::string output, obj_frames;
    int intensity = kMaxExpressionIntensity;
    int fps = 60;
    double seconds = 1.0;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = app.add_subcommand(
      "expressions",
      "The six FAP 2 expressions on the ICT face (spec/expressions.tsv): as OBJ targets in a folder "
      "(cm), or as a .glb with six morph targets animated one after another (metres)");
  cmd->add_option("-o,--output", args->output, "Output folder, or OUT.glb")->required();
  cmd->add_option("--intensity", args->intensity, "FAP 2 intensity of the OBJ targets, 0..63")
      ->check(CLI::Range(0, kMaxExpressionIntensity))
      ->capture_default_str();
  cmd->add_option("--fps", args->fps, ".glb: frames per second")->check(CLI::Range(1, 1000))->capture_default_str();
  cmd->add_option("--seconds", args->seconds, ".glb: seconds per expression")
      ->check(CLI::Range(0.05, 60.0))
      ->capture_default_str();
  cmd->add_option("--obj-frames-out", args->obj_frames, ".glb: also write every frame as OBJ (metres) into this folder");
  cmd->callback([args] {
    if (cli::is_mesh_output(args->output)) cli::check_output_writable(args->output);  // before the face is loaded
    const FaceModel& face = ict_face_model();
    if (!cli::is_mesh_output(args->output)) {
      if (!args->obj_frames.empty()) throw cli::UsageError("expressions: --obj-frames-out needs a .glb output");
      write_expression_targets(face, args->intensity, write_into(args->output));
      std::cout << "expressions: 6 OBJ targets -> " << args->output << "\n";
      return;
    }
    std::vector<Positions> targets;
    std::vector<std::string> names;
    for (const auto e : all_expressions()) {
      targets.push_back(expression_displacement(face, {e, args->intensity}));
      names.emplace_back(expression_name(e));
    }
    const auto animation = fapcast::morph_animation_from_cm(
        face.neutral_cm, face.faces, targets, names, expression_tour(args->fps, args->seconds),
        FrameRate{static_cast<std::uint32_t>(args->fps), 1}, "fapcast-expressions");
    write_file_atomically(args->output, write_glb(animation));
    std::cout << "expressions: " << animation.weights.rows() << " frames, 6 morph targets -> "
              << args->output << "\n";
    if (!args->obj_frames.empty())
      std::cout << "expressions: " << fapcast::write_obj_frames(animation, args->obj_frames)
                << " OBJ frames -> " << args->obj_frames << "\n";
  });
}};

const cli::Registration render_command{"render", [](CLI::App& app) {
  struct Args {
    std::string input, output, view = "face";
    int width = 320, every = 1;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = app.add_subcommand(
      "render", "Render the frames of a .glb morph animation headlessly (flat Lambert shading, "
                "z-buffer, orthographic front view) as PPM images, to look at the mouth moving");
  cmd->add_option("IN", args->input, "Input .glb (one mesh, a weights animation)")->required();
  cmd->add_option("-o,--output", args->output, "Output folder for frame_NNNNNN.ppm (created)")->required();
  cmd->add_option("--view", args->view, "face: the whole mesh; mouth: where the targets move")
      ->check(CLI::IsMember({"face", "mouth"}))
      ->capture_default_str();
  cmd->add_option("--width", args->width, "Image width in pixels")->check(CLI::Range(16, 4096))->capture_default_str();
  cmd->add_option("--every", args->every, "Render every Nth frame")->check(CLI::Range(1, 1000000))->capture_default_str();
  cmd->callback([args] {
    const auto animation = read_glb(read_file(args->input), args->input);
    const auto box = args->view == "mouth"
                         ? fapcast::moving_view(animation.base_positions_m, animation.targets_m)
                         : fapcast::whole_view(animation.base_positions_m);
    const fs::path dir = args->output;
    fs::create_directories(dir);
    const Eigen::Index frames = std::max<Eigen::Index>(animation.weights.rows(), 1);
    std::size_t written = 0;
    for (Eigen::Index f = 0; f < frames; f += args->every) {
      const Eigen::Matrix3Xf positions = animation.weights.rows() > 0
                                             ? frame_positions(animation, f)
                                             : animation.base_positions_m;
      char name[32];
      std::snprintf(name, sizeof name, "frame_%06ld.ppm", static_cast<long>(f));
      write_file_atomically(
          dir / name, fapcast::to_ppm(fapcast::render_front(positions, animation.triangles, box, args->width)));
      ++written;
    }
    std::cout << "render: " << written << " frames -> " << args->output << "\n";
  });
}};

}  // namespace
