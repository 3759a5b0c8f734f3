#pragma once
// Timed phones from a phone alignment on the WAV timeline, for synthesis from recorded speech
// (`fapcast animate`).
#include "fapcast/core/input_error.hpp"
#include "fapcast/corpus/alignment_file.hpp"
#include "fapcast/phonetics/timed_phone.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace fapcast {

// How an animation shows an audible inhalation (LabelKind::breath): as HH, the open glottis with
// the lips parted. Speech inhalations are mostly taken through the open mouth (spec/talker.md,
// "Calibration against real articulography").
inline constexpr Phone kInhalationPhone = Phone::HH;

// One TimedPhone per segment of an alignment file (alignment_file.hpp), times rounded to
// samples with to_sample: phones as they are, silence and noise as SIL, an inhalation as
// `breath_as` (SIL where it is compared as a pause, kInhalationPhone to animate it). A closure joined with its
// release is one phone from the closure's start (as the front-end's closures are). Throws InputError (source, rule "time-off-sample-grid") naming the segment
// when a time is beyond what a sample count holds.
std::vector<TimedPhone> timed_phones(const std::vector<AlignedSegment>& segments, SampleRate sample_rate,
                                     const std::string& source, Phone breath_as = Phone::SIL);

// An alignment and its WAV rarely end on the same sample. Phones running past the audio's
// `audio_samples` by at most `tolerance_samples` are cut at its end (phones starting there are
// dropped); further is an error (InputError source, rule "alignment-longer-than-audio": the
// alignment is for another recording). An alignment that ends early is fine: synthesis fills
// the rest with silence (place_on_voice_grid's end_sample).
std::vector<TimedPhone> fit_phones_to_audio(std::vector<TimedPhone> phones, std::int64_t audio_samples,
                                            std::int64_t tolerance_samples, const std::string& source);

}  // namespace fapcast
