#include "rig_output.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>

#include "animation.hpp"
#include "command.hpp"
#include "file_extension.hpp"
#include "fapcast/core/file_io.hpp"
#include "fapcast/face/face_model.hpp"
#include "fapcast/rig/arkit_fit.hpp"
#include "fapcast/rig/avatar_glb.hpp"
#include "fapcast/rig/live_link_csv.hpp"
#include "fapcast/rig/mouth_visemes.hpp"
#include "fapcast/rig/talkinghead_json.hpp"
#include "fapcast/rig/vmc_osc.hpp"
#include "fapcast/rig/vrm_animation.hpp"
#include "fapcast/transport/paced_datagrams.hpp"
#include "fapcast/transport/udp_url.hpp"

namespace fapcast::cli {

namespace {

std::optional<RigName> parse_rig(const std::string& text) {
  if (text == "arkit") return RigName::kArkit;
  if (text == "oculus") return RigName::kOculus;
  if (text == "vrm") return RigName::kVrm;
  if (text == "vrm0") return RigName::kVrm0;
  return std::nullopt;
}

std::string read_whole(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The rig's names and per-frame weights (frames x names).
struct RigTrack {
  std::vector<std::string> names;
  Eigen::MatrixXf weights;
};

}  // namespace

bool is_rig_output(const std::filesystem::path& output, const RigArgs& rig) {
  const std::string ext = lower_extension(output);
  return ext == ".csv" || ext == ".vrma" || (ext == ".glb" && !rig.avatar.empty()) ||
         (ext == ".json" && !rig.rig_text.empty());
}

void check_rig_args(const std::string& command, const std::filesystem::path& output, RigArgs& rig) {
  const std::string ext = lower_extension(output);
  if (!rig.rig_text.empty()) {
    rig.rig = parse_rig(rig.rig_text);
    if (!rig.rig) throw UsageError(command + ": --rig '" + rig.rig_text + "' is not one of arkit, oculus, vrm, vrm0");
  }
  if (!rig.avatar.empty() && ext != ".glb")
    throw UsageError(command + ": --avatar animates a .glb: the output must end in .glb");
  if (ext == ".csv") {
    if (rig.rig && *rig.rig != RigName::kArkit) throw UsageError(command + ": a .csv is Live Link Face's: --rig arkit");
    rig.rig = RigName::kArkit;
  } else if (ext == ".vrma") {
    if (rig.rig && *rig.rig != RigName::kVrm && *rig.rig != RigName::kArkit)
      throw UsageError(command + ": a .vrma holds VRM 1.0 expressions: --rig vrm, or arkit (custom expressions)");
    if (!rig.rig) rig.rig = RigName::kVrm;
  } else if (ext == ".json" && rig.rig) {
    if (*rig.rig != RigName::kArkit && *rig.rig != RigName::kOculus)
      throw UsageError(command + ": the TalkingHead JSON drives ARKit or Oculus morph targets: --rig arkit|oculus");
  } else if (ext == ".glb" && !rig.avatar.empty()) {
    if (rig.rig && *rig.rig != RigName::kArkit && *rig.rig != RigName::kOculus)
      throw UsageError(command + ": an avatar's morph targets are driven by ARKit or Oculus names: --rig arkit|oculus");
  } else if (rig.rig && rig.vmc.empty()) {
    throw UsageError(command + ": --rig needs a rig output (.csv, .vrma, .json, --avatar X.glb) or --vmc");
  }
  if (!rig.vmc.empty()) {
    UdpUrl url;
    if (parse_udp_url(rig.vmc, url) || url.port == 0)
      throw UsageError(command + ": --vmc '" + rig.vmc + "' is not udp://HOST:PORT with a port");
  }
}

std::string write_rig_outputs(const RigArgs& args, const std::filesystem::path& output, const Voice& voice,
                              const SynthesizedTrack& track, std::int64_t audio_samples, bool write_file,
                              std::span<const TimedWord> words) {
  const FrameRate rate{static_cast<std::uint32_t>(Voice::kFramesPerSecond), 1};
  const std::int64_t shown =
      std::min<std::int64_t>(frames_shown(audio_samples, rate, track.timeline.sample_rate), track.pca_frames.rows());
  const ArkitFit fit(ict_face_model(), voice);
  const ArkitTrack arkit = fit.fit(track.pca_frames.topRows(shown), track.tongue.topRows(shown));
  std::vector<Phone> phone_per_frame(static_cast<std::size_t>(shown), Phone::SIL);
  for (std::size_t i = 0; i < track.timeline.phones.size(); ++i)
    for (auto f = track.timeline.phones[i].first_frame; f < std::min<std::int64_t>(track.timeline.phones[i].end_frame, shown); ++f)
      phone_per_frame[static_cast<std::size_t>(f)] = track.timeline.phone_of[i];

  const std::string ext = lower_extension(output);
  std::optional<Avatar> avatar;
  RigName rig = args.rig.value_or(RigName::kVrm0);
  if (!args.avatar.empty()) {
    avatar = read_avatar(read_whole(args.avatar), args.avatar);
    if (!args.rig) {  // ARKit when the avatar has any ARKit shape, else Oculus
      bool has_arkit = false;
      for (const AvatarMesh& m : avatar->meshes)
        for (const std::string& t : m.targets) has_arkit = has_arkit || arkit_index(t).has_value();
      rig = has_arkit ? RigName::kArkit : RigName::kOculus;
    }
  }
  RigTrack out;
  std::optional<MouthVisemes> visemes;
  if (rig != RigName::kArkit) visemes.emplace(fit, voice);
  if (rig == RigName::kArkit) {
    for (const ArkitShape& s : kArkitShapes) out.names.emplace_back(s.name);
    out.weights = arkit.weights;
  } else if (rig == RigName::kOculus) {
    for (std::string_view n : kOculusMorphNames) out.names.emplace_back(n);
    out.weights = visemes->oculus(arkit.weights, phone_per_frame);
  } else {
    const auto& names = rig == RigName::kVrm ? kVrmVowelNames : kVrm0VowelNames;
    for (std::string_view n : names) out.names.emplace_back(n);
    out.weights = visemes->vrm(arkit.weights);
  }

  std::ostringstream summary;
  if (write_file && is_rig_output(output, args)) {
    if (ext == ".csv") {
      write_file_atomically(output, live_link_csv(arkit.weights, rate));
    } else if (ext == ".vrma") {
      write_file_atomically(output, write_vrm_animation(out.names, out.weights, rate));
    } else if (ext == ".json") {
      std::vector<TimedText> timed;
      const double ms = 1000.0 / static_cast<double>(track.timeline.sample_rate.hz);
      for (const TimedWord& w : words)
        timed.push_back({w.text, static_cast<double>(w.start_sample) * ms,
                         static_cast<double>(w.end_sample - w.start_sample) * ms});
      write_file_atomically(output, talkinghead_json(timed, oculus_viseme_timeline(phone_per_frame), out.names, out.weights, rate));
    } else {
      const AvatarAnimation animated = animate_avatar(*avatar, out.names, out.weights, rate, "fapcast speech");
      write_file_atomically(output, animated.bytes);
      summary << "; avatar " << args.avatar << ": " << animated.driven.size() << " morph targets driven";
      if (!animated.unknown.empty()) summary << ", " << animated.unknown.size() << " left at rest";
    }
  }
  summary << "; ARKit fit: lips " << 1000.0 * arkit.residual.lips_rms_m << " mm RMS (max "
          << 1000.0 * arkit.residual.lips_max_m << "), jaw " << 1000.0 * arkit.residual.jaw_rms_m << " mm";
  if (!args.vmc.empty()) {
    asio::io_context io;
    UdpSender sender(io, resolve_udp_url(io, args.vmc));
    std::vector<TimedDatagram> datagrams(static_cast<std::size_t>(shown));
    std::vector<float> values(out.names.size());
    for (std::int64_t f = 0; f < shown; ++f) {
      for (std::size_t j = 0; j < values.size(); ++j) values[j] = out.weights(f, static_cast<Eigen::Index>(j));
      const auto at = std::chrono::nanoseconds(f * 1'000'000'000LL / Voice::kFramesPerSecond);
      datagrams[static_cast<std::size_t>(f)] = {at, vmc_blend_bundle(out.names, values, static_cast<float>(f) / Voice::kFramesPerSecond)};
    }
    std::error_code ec;
    const PacedSendReport sent = send_paced(sender, datagrams, true, ec);
    if (ec) throw std::runtime_error(args.vmc + ": " + ec.message());
    summary << "; VMC " << args.vmc << ": " << sent.sent << " bundles in real time (latest "
            << std::chrono::duration<double, std::milli>(sent.late_max).count() << " ms late)";
  }
  return summary.str();
}

}  // namespace fapcast::cli
