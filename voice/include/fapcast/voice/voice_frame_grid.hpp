#pragma once
// The voice's 60 fps frame grid on the WAV timeline, and timed phones placed on it: frame n is
// shown from frame_to_sample(n, kVoiceFrameRate, rate) (core/frame_rate.hpp, the one
// frame <-> sample rule). Timed phones -> target phones for the unit search and concatenation.
#include "fapcast/core/input_error.hpp"
#include "fapcast/core/frame_rate.hpp"
#include "fapcast/phonetics/timed_phone.hpp"
#include "fapcast/phonetics/viseme.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace fapcast {

// A target phone on the output frame grid (the voice's frame rate, 60 fps): frames
// [first_frame, end_frame). `hold` marks a phone whose shape must be met, not smoothed away
// (the closure of /p b m/, lip to teeth of /f v/).
struct TargetPhone {
  VisemeClass viseme = VisemeClass::kSilence;
  std::int64_t first_frame = 0;
  std::int64_t end_frame = 0;
  bool hold = false;
};

// The corpus / PCA frame rate of every voice (paper section 3.2: 60 fps capture).
inline constexpr std::int64_t kVoiceFramesPerSecond = 60;
inline constexpr FrameRate kVoiceFrameRate{static_cast<std::uint32_t>(kVoiceFramesPerSecond), 1};

// Timed phones on the voice grid. Phone i's frames are [first_frame_at(start), first_frame_at(end))
// at kVoiceFrameRate: every frame belongs to the phone on screen when it is shown.
// Rules (spec/synthesis.md, "Input phones"):
//  - phones must be in time order and must not overlap (InputError "phone-overlap"); an end
//    before its start is "phone-reversed", a negative start "phone-negative-start";
//  - a phone of zero duration, or one too short to own a frame (< 1/60 s between two frame
//    instants), is dropped: its neighbours meet where it was (counted in `dropped`);
//  - a gap before the first phone, between phones or up to `end_sample` is silence (a SIL
//    target; counted in `gaps_filled`), so the track starts at frame 0 = sample 0;
//  - /p b m/ and /f v/ are held (TargetPhone::hold): the smoother must not round their shape.
struct TargetTimeline {
  SampleRate sample_rate;
  std::vector<TargetPhone> phones;     // contiguous from frame 0
  std::vector<Phone> phone_of;         // the phone of each target (SIL for filled gaps)
  std::size_t dropped = 0;
  std::size_t gaps_filled = 0;
  std::int64_t frame_count() const { return phones.empty() ? 0 : phones.back().end_frame; }
};

// `end_sample` (e.g. the audio's length) extends the timeline with silence when it lies past
// the last phone; phones running past it are the caller's concern (see tools' animate).
// Throws InputError (source `source`, rule as above, detail naming the phone index: phones[0]
// is phone `first_phone` of the text, as in a piece of a longer one) or std::invalid_argument
// for an invalid sample rate.
TargetTimeline place_on_voice_grid(std::span<const TimedPhone> phones, SampleRate sample_rate,
                                   std::int64_t end_sample = 0, const std::string& source = "phones", std::size_t first_phone = 0);

// Whether a phone's visible shape must be met exactly (lip closure, lip to teeth).
constexpr bool is_held(VisemeClass v) {
  return v == VisemeClass::kBilabial || v == VisemeClass::kLabiodental;
}

}  // namespace fapcast
