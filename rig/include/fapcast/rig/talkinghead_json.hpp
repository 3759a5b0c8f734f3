#pragma once
// The JSON track TalkingHead (met4citizen/TalkingHead, `speakAudio`) and other three.js players read
// (spec/rigs.md, "TalkingHead JSON"): the words and visemes with start times and durations in
// milliseconds, and an `anim` template of ARKit blend-shape values per frame:
//   {"words": [...], "wtimes": [...], "wdurations": [...],
//    "visemes": ["sil", "PP", "aa", ...], "vtimes": [...], "vdurations": [...],
//    "anim": {"name": "fapcast", "dt": [ms per frame ...], "vs": {"jawOpen": [...], ...}},  (morph targets by name)
//    "fps": 60, "generator": "fapcast"}
// A player passes it with the audio: head.speakAudio({audio, ...track}). Viseme names are
// TalkingHead's (viseme_ + name is the avatar's morph target: sil PP FF TH DD kk CH SS nn RR aa E I O U).
#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "fapcast/core/frame_rate.hpp"
#include "fapcast/rig/mouth_visemes.hpp"

namespace fapcast {

struct TimedText {
  std::string text;
  double start_ms = 0;
  double duration_ms = 0;
};

// `visemes`: the viseme shown in each frame (oculus_viseme_timeline), merged into runs; `weights`:
// frames x names (ARKit shapes or viseme_* morph targets); frame f lasts 1000 / rate ms. Only
// names non-zero in some frame are listed in anim.vs.
std::string talkinghead_json(std::span<const TimedText> words, std::span<const OculusViseme> visemes,
                             std::span<const std::string> names, const Eigen::MatrixXf& weights, FrameRate rate);

}  // namespace fapcast
