#pragma once
// Timed phones from a phone alignment (a TextGrid's phone tier or a .lab file) on the WAV
// timeline, for synthesis from recorded speech (`fapcast animate`).
#include "fapcast/core/input_error.hpp"
#include "fapcast/corpus/alignment.hpp"
#include "fapcast/phonetics/timed_phone.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace fapcast {

// The tier that holds the phones: the first interval tier named "phones" or "phone"
// (any case), else the first interval tier; nullptr when the alignment has none.
const LabelTier* phone_tier(const Alignment& alignment);

// One TimedPhone per interval (times rounded to samples with to_sample). Labels: ARPAbet with
// or without stress ("AH0", "sil"), TIMIT/MOCHA labels ("h#", "pau", "sp", "dcl"), and the empty
// label of an unlabelled gap, which is silence. A TIMIT closure ("dcl") directly followed by its
// release ("d") becomes one phone, as the front-end's closures are. Throws InputError (source,
// rule "phone-label") naming the interval and its label when a label is none of these.
std::vector<TimedPhone> phones_from_tier(const LabelTier& tier, SampleRate sample_rate,
                                         const std::string& source);

// An alignment and its WAV rarely end on the same sample. Phones running past the audio's
// `audio_samples` by at most `tolerance_samples` are cut at its end (phones starting there are
// dropped); further is an error (InputError source, rule "alignment-longer-than-audio": the
// alignment is for another recording). An alignment that ends early is fine: synthesis fills
// the rest with silence (place_on_voice_grid's end_sample).
std::vector<TimedPhone> fit_phones_to_audio(std::vector<TimedPhone> phones, std::int64_t audio_samples,
                                            std::int64_t tolerance_samples, const std::string& source);

}  // namespace fapcast
