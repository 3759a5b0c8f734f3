#pragma once
// What the cached default voice is keyed by (spec/voice.md "The default voice"): a change of the
// reference talker's tables or of the build's recipe gives the cache file another name, so every
// machine rebuilds the default voice instead of keeping the old talker.
#include <cstdint>
#include <span>
#include <string>

#include "fapcast/builder/voice_prototypes.hpp"
#include "fapcast/talker/articulation.hpp"

namespace fapcast::cli {

// Bumped by hand when code that shapes the default voice changes without changing a table below
// (the talker's marker synthesis, capture imperfections, the recording script, the build, how
// the corpus is recorded: 4 records it in a fresh process, default_voice.cpp; 5 gives corpus
// frames to phones by synthesis's frame rule, voice_corpus.cpp; 6 records the schwa as AX, the
// 41st phone, with a viseme class of its own; 7 keeps the phones espeak-ng gives no samples of
// their own, text_frontend.cpp, and spells the nonsense items so that espeak-ng says them as
// asked, recording_script.cpp; 8 lets every phone's jaw anticipate, articulation.cpp; 9 writes
// the nonsense items' rhotic class as the consonant R, not the vowel ER, recording_script.cpp;
// 10 opens every phone's jaw 1.4 times as far above the sibilants' and the lips' own opening
// 1.2 times as far, articulation.cpp: a table change, numbered so that spec/ can name the voice;
// 11 adds the retargeting's lip-contact term, lip_contact_fit.cpp, so that every /p b m/ closes;
// 12 pattern-fills the long marker gaps from a marker on the same lip, pattern_fill.cpp).
inline constexpr std::uint32_t kDefaultVoiceRecipe = 12;

// CRC-32, as 8 lower-case hex digits, of the recipe number, the corpus seed, every row of the
// articulation and shape tables and of the prototype details, and the prototype rules.
std::string default_voice_key(std::uint64_t seed, std::span<const PhoneChannelTarget> articulation,
                              std::span<const ChannelShapeRow> shapes,
                              std::span<const PrototypeShapeWeight> details);

// The key of the tables compiled in (articulation_table(), channel_shape_table(),
// target_prototype_details()).
std::string default_voice_key(std::uint64_t seed);

}  // namespace fapcast::cli
