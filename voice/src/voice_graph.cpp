#include "fapcast/voice/voice_graph.hpp"

#include <cstring>
#include <stdexcept>

#include "fapcast/core/input_error.hpp"
#include "fapcast/phonetics/viseme.hpp"

namespace fapcast {
namespace {

template <class T>
void put(std::vector<std::byte>& out, T value) {
  for (std::size_t i = 0; i < sizeof(T); ++i)
    out.push_back(static_cast<std::byte>((static_cast<std::uint64_t>(value) >> (8 * i)) & 0xFF));
}

template <class T>
T get(std::span<const std::byte> bytes, std::size_t at) {
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < sizeof(T); ++i)
    v |= static_cast<std::uint64_t>(std::to_integer<std::uint8_t>(bytes[at + i])) << (8 * i);
  return static_cast<T>(v);
}

}  // namespace

std::vector<std::byte> encode_voice_graph(const VoiceGraphData& data) {
  if (data.phones.size() != data.states.size())
    throw std::invalid_argument("encode_voice_graph: " + std::to_string(data.phones.size()) + " phones for " +
                                std::to_string(data.states.size()) + " states");
  std::vector<std::byte> out;
  out.reserve(kVoiceGraphHeaderBytes + kVoiceGraphStateBytes * data.states.size() +
              kVoiceGraphUtteranceBytes * data.utterances.size());
  put<std::uint32_t>(out, kVoiceGraphLayoutVersion);
  put<std::uint32_t>(out, static_cast<std::uint32_t>(data.states.size()));
  put<std::uint32_t>(out, static_cast<std::uint32_t>(data.utterances.size()));
  put<std::uint32_t>(out, data.frame_count);
  for (std::size_t j = 0; j < data.states.size(); ++j) {
    const PhoneState& s = data.states[j];
    put<std::uint32_t>(out, s.utterance);
    put<std::uint32_t>(out, s.frames.first);
    put<std::uint32_t>(out, s.frames.count);
    put<std::uint8_t>(out, static_cast<std::uint8_t>(s.viseme));
    put<std::uint8_t>(out, static_cast<std::uint8_t>(data.phones[j]));
    put<std::uint16_t>(out, 0);
  }
  for (const FrameSpan& u : data.utterances) {
    put<std::uint32_t>(out, u.first);
    put<std::uint32_t>(out, u.count);
  }
  try {  // the writer never emits a section the reader refuses
    (void)decode_voice_graph(out, "<encode_voice_graph>", 0);
  } catch (const InputError& e) {
    throw std::invalid_argument(e.what());
  }
  return out;
}

VoiceGraphData decode_voice_graph(std::span<const std::byte> bytes, const std::string& source,
                                  std::uint64_t section_offset) {
  const auto refuse = [&](std::size_t at, const char* rule, const std::string& detail) {
    throw InputError({source, std::nullopt, section_offset + at}, rule, "section 'GRPH' (phone graph): " + detail);
  };
  if (bytes.size() < kVoiceGraphHeaderBytes)
    refuse(0, "graph-truncated", std::to_string(bytes.size()) + " bytes, the header needs 16");
  const auto version = get<std::uint32_t>(bytes, 0);
  if (version != kVoiceGraphLayoutVersion)
    refuse(0, "graph-version", "layout version " + std::to_string(version) + ", this reader knows " +
                                         std::to_string(kVoiceGraphLayoutVersion) +
                                         (version == 1 ? " (1 numbers the phones before AX was added: build the voice again)" : ""));
  const std::uint64_t states = get<std::uint32_t>(bytes, 4);
  const std::uint64_t utterances = get<std::uint32_t>(bytes, 8);
  VoiceGraphData data;
  data.frame_count = get<std::uint32_t>(bytes, 12);
  const std::uint64_t expected =
      kVoiceGraphHeaderBytes + kVoiceGraphStateBytes * states + kVoiceGraphUtteranceBytes * utterances;
  if (expected != bytes.size())
    refuse(4, "graph-size", std::to_string(states) + " states and " + std::to_string(utterances) +
                                " utterances need " + std::to_string(expected) + " bytes, the section has " +
                                std::to_string(bytes.size()));
  const std::size_t utterance_at = kVoiceGraphHeaderBytes + kVoiceGraphStateBytes * states;
  std::uint64_t next_first = 0;
  for (std::size_t u = 0; u < utterances; ++u) {
    const std::size_t at = utterance_at + kVoiceGraphUtteranceBytes * u;
    const FrameSpan span{get<std::uint32_t>(bytes, at), get<std::uint32_t>(bytes, at + 4)};
    if (span.first != next_first || span.count == 0)
      refuse(at, "graph-span", "utterance " + std::to_string(u) + " spans frames [" + std::to_string(span.first) +
                                   ", +" + std::to_string(span.count) + "), expected a non-empty span from frame " +
                                   std::to_string(next_first));
    next_first = std::uint64_t{span.first} + span.count;
    data.utterances.push_back(span);
  }
  if (next_first != data.frame_count)
    refuse(12, "graph-span", "the utterances cover " + std::to_string(next_first) + " frames, the header says " +
                                 std::to_string(data.frame_count));
  data.states.reserve(states);
  data.phones.reserve(states);
  std::uint64_t previous_end = 0;
  for (std::size_t j = 0; j < states; ++j) {
    const std::size_t at = kVoiceGraphHeaderBytes + kVoiceGraphStateBytes * j;
    PhoneState s;
    s.utterance = get<std::uint32_t>(bytes, at);
    s.frames = {get<std::uint32_t>(bytes, at + 4), get<std::uint32_t>(bytes, at + 8)};
    const auto viseme = get<std::uint8_t>(bytes, at + 12);
    const auto phone = get<std::uint8_t>(bytes, at + 13);
    const auto reserved = get<std::uint16_t>(bytes, at + 14);
    const std::string name = "state " + std::to_string(j);
    if (s.utterance >= utterances)
      refuse(at, "graph-state", name + " belongs to utterance " + std::to_string(s.utterance) + " of " +
                                    std::to_string(utterances));
    if (phone >= kPhoneCount || viseme >= kVisemeClassCount || reserved != 0)
      refuse(at + 12, "graph-state", name + " has phone " + std::to_string(phone) + ", viseme " +
                                         std::to_string(viseme) + ", reserved " + std::to_string(reserved));
    const auto p = static_cast<Phone>(phone);
    s.viseme = static_cast<VisemeClass>(viseme);
    if (search_viseme(p) != s.viseme)
      refuse(at + 12, "graph-state", name + ": phone " + std::string(arpabet(p)) + " is not of viseme class " +
                                         std::string(viseme_class_name(s.viseme)));
    const bool same_utterance = j > 0 && data.states.back().utterance == s.utterance;
    if (j > 0 && (s.utterance < data.states.back().utterance || (same_utterance && s.frames.first < previous_end)))
      refuse(at, "graph-order", name + " is out of order (utterances ascending, spans in time order, no overlap)");
    const FrameSpan& u = data.utterances[s.utterance];
    if (s.frames.count == 0 || s.frames.first < u.first ||
        std::uint64_t{s.frames.first} + s.frames.count > std::uint64_t{u.first} + u.count)
      refuse(at + 4, "graph-span", name + " spans frames [" + std::to_string(s.frames.first) + ", +" +
                                       std::to_string(s.frames.count) + "), outside utterance " +
                                       std::to_string(s.utterance) + " or empty");
    previous_end = std::uint64_t{s.frames.first} + s.frames.count;
    data.states.push_back(s);
    data.phones.push_back(p);
  }
  return data;
}

}  // namespace fapcast
