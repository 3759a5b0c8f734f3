#pragma once
// What a live client receives over the WebSocket (spec/serve.md, "The live stream"): JSON text
// messages that announce sessions and sentences, and one binary message per frame that carries
// the frame's morph weights and the audio played while it is shown, so that sound and face
// arrive together and the player needs no second clock.
//
// Frame message, little-endian (what browsers' typed arrays read natively):
//   offset 0  u8   type = 1 (frame)
//          1  u8   flags: bit 0 = first frame of a sentence
//          2  u16  K, morph weights that follow
//          4  u32  session number (as announced by its "session" message)
//          8  i64  sample: the frame's first sample on the session's timeline (the audio rate)
//         16  u32  audio samples that follow (mono int16)
//         20  u32  frame index within the session
//         24  f32[K] the k PCA weights of the voice's face (the morph targets of /v1/face.glb)
//   24 + 4K  i16[n] the audio from `sample` to the next frame's sample
#include <cstdint>
#include <span>
#include <string>
#include <system_error>
#include <vector>

namespace fapcast {

inline constexpr std::uint8_t kLiveFrameType = 1;
inline constexpr std::uint8_t kLiveFirstOfSentence = 1;
inline constexpr std::size_t kLiveFrameHeaderBytes = 24;
inline constexpr std::size_t kLiveMaxWeights = 256;
inline constexpr std::size_t kLiveMaxAudio = 48'000;  // one second at 48 kHz: far above one frame

struct LiveFrame {
  bool first_of_sentence = false;
  std::uint32_t session = 0;
  std::int64_t sample = 0;
  std::uint32_t index = 0;
  std::vector<float> weights;
  std::vector<std::int16_t> audio;
  bool operator==(const LiveFrame&) const = default;
};

// Appends the binary message of `frame`.
void encode_live_frame(std::span<const float> weights, std::span<const std::int16_t> audio, std::uint32_t session,
                       std::int64_t sample, std::uint32_t index, bool first_of_sentence, std::string& out);
// Parses one message. Errors (std::errc): invalid_argument for a wrong type or a length that
// disagrees with the counts, value_too_large for counts above the limits.
std::error_code decode_live_frame(std::span<const std::uint8_t> message, LiveFrame& out);

}  // namespace fapcast
