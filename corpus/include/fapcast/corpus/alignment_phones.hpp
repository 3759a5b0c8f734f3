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

// How the audible inhalations of an alignment (LabelKind::breath) become phones.
struct BreathAs {
  Phone phone = Phone::SIL;  // what the inhalation shows as
  double runs_on_s = 0.0;    // how far past its labelled end it runs on over the pause after it
};

// Where alignments are compared: a breath is a pause like any other.
inline constexpr BreathAs kBreathAsPause{};

// Where an animation shows it: the mouth open for the inhalation, neither rounded nor spread (the
// schwa, AX), until the next phone starts, at most 0.3 s past the breath's labelled end. A label
// marks the audible noise; the mouth opens with the inhalation and stays open until speech starts
// (spec/talker.md, "Calibration against real articulography"). The 0.3 s is an assumption, not
// fitted: fsew0_001's only breath is followed by 0.07 s of pause.
inline constexpr BreathAs kInhalation{Phone::AX, 0.3};

// One TimedPhone per segment of an alignment file (alignment_file.hpp), times rounded to
// samples with to_sample: phones as they are, silence and noise as SIL, an inhalation as
// `breath.phone`, run on over the silence segments right after it by up to `breath.runs_on_s`
// (a silence it covers whole is dropped, one it reaches into starts where the run-on ends). A
// closure joined with its release is one phone from the closure's start (as the front-end's
// closures are). Throws InputError (source, rule "time-off-sample-grid") naming the segment when
// a time is beyond what a sample count holds.
std::vector<TimedPhone> timed_phones(const std::vector<AlignedSegment>& segments, SampleRate sample_rate,
                                     const std::string& source, BreathAs breath = kBreathAsPause);

// An alignment and its WAV rarely end on the same sample. Phones running past the audio's
// `audio_samples` by at most `tolerance_samples` are cut at its end (phones starting there are
// dropped); further is an error (InputError source, rule "alignment-longer-than-audio": the
// alignment is for another recording). An alignment that ends early is fine: synthesis fills
// the rest with silence (place_on_voice_grid's end_sample).
std::vector<TimedPhone> fit_phones_to_audio(std::vector<TimedPhone> phones, std::int64_t audio_samples,
                                            std::int64_t tolerance_samples, const std::string& source);

}  // namespace fapcast
