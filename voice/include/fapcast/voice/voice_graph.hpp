#pragma once
// The GRPH section of a voice (spec/voice.md, "Phone graph layout"): the phone states of every
// corpus utterance - utterance, frame span, viseme class and ARPAbet phone - and each utterance's
// frame span, in a fixed little-endian binary layout. The search's indices (by viseme class and
// diviseme, join features) are rebuilt from it at open (PhoneGraph), which is O(states).
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "fapcast/core/input_error.hpp"
#include "fapcast/phonetics/phone.hpp"
#include "fapcast/select/phone_graph.hpp"

namespace fapcast {

// 2: the 41 phones of phone.hpp (AX added), class 20 the schwa. 1 had 40 phones, class 20 AW's.
inline constexpr std::uint32_t kVoiceGraphLayoutVersion = 2;
inline constexpr std::size_t kVoiceGraphHeaderBytes = 16;
inline constexpr std::size_t kVoiceGraphStateBytes = 16;
inline constexpr std::size_t kVoiceGraphUtteranceBytes = 8;

struct VoiceGraphData {
  std::vector<PhoneState> states;    // utterances contiguous, spoken order
  std::vector<Phone> phones;         // one per state
  std::vector<FrameSpan> utterances; // frame span of each utterance (U of them)
  std::uint32_t frame_count = 0;     // F: rows of FCOE
  friend bool operator==(const VoiceGraphData&, const VoiceGraphData&) = default;
};

// The section bytes. Throws std::invalid_argument when `data` breaks a rule decode checks.
std::vector<std::byte> encode_voice_graph(const VoiceGraphData& data);

// Parses and checks the section: `source` names the file and `section_offset` is the section's
// byte offset in it (errors give the absolute offset). Throws InputError with rules
// graph-truncated, graph-version, graph-size, graph-state, graph-order, graph-span.
VoiceGraphData decode_voice_graph(std::span<const std::byte> bytes, const std::string& source,
                                  std::uint64_t section_offset);

}  // namespace fapcast
