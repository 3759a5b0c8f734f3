#pragma once
// `say|animate --rig arkit|oculus|vrm|vrm0 [--avatar IN.glb] [--vmc udp://HOST:PORT]`: the
// synthesis as the weights of an avatar rig (spec/rigs.md) - Live Link Face CSV, TalkingHead JSON,
// VRM animation, the user's avatar animated by name, and a live VMC stream.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

#include "fapcast/frontend/text_frontend.hpp"
#include "fapcast/synthesis/synthesis.hpp"
#include "fapcast/voice/voice.hpp"

namespace fapcast::cli {

enum class RigName { kArkit, kOculus, kVrm, kVrm0 };

struct RigArgs {
  std::string rig_text;               // as given: --rig
  std::string avatar;                 // --avatar IN.glb
  std::string vmc;                    // --vmc udp://HOST:PORT
  std::optional<RigName> rig;         // resolved before the run (rig_of)
};

// Whether `output` is a rig format: .csv, .vrma, a .glb with --avatar, a .json with --rig.
bool is_rig_output(const std::filesystem::path& output, const RigArgs& rig);

// Checks the rig options against the output before any work and resolves the rig (UsageError):
// .csv is ARKit, .vrma VRM (or ARKit as custom expressions), a .glb needs --avatar to be a rig
// output; --vmc alone streams VRM 0.x vowels unless --rig says otherwise.
void check_rig_args(const std::string& command, const std::filesystem::path& output, RigArgs& rig);

// Fits the rig on `track` (the frames shown while the audio plays), writes `output` when it is a
// rig format and streams the frames over VMC when asked; returns a summary for the command's line.
std::string write_rig_outputs(const RigArgs& rig, const std::filesystem::path& output, const Voice& voice,
                              const SynthesizedTrack& track, std::int64_t audio_samples, bool write_file,
                              std::span<const TimedWord> words);

}  // namespace fapcast::cli
