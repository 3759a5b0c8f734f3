// Fuzzes decode_live_frame (the binary frame message of the live WebSocket stream) and its
// encoder: any message either decodes or is refused with invalid_argument or value_too_large;
// what decodes keeps the limits and encodes back to the same bytes (the flags byte to its one
// defined bit). Then the input's bytes are read as a frame to encode, and that message decodes
// to the same frame, bit for bit.
#include "fapcast/serve/live_message.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <system_error>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapcast;
  const std::span<const std::uint8_t> in(data, size);
  LiveFrame frame;
  const std::error_code ec = decode_live_frame(in, frame);
  if (ec) {
    if (ec != std::errc::invalid_argument && ec != std::errc::value_too_large) __builtin_trap();
  } else {
    if (frame.weights.size() > kLiveMaxWeights || frame.audio.size() > kLiveMaxAudio) __builtin_trap();
    std::string out;
    encode_live_frame(frame.weights, frame.audio, frame.session, frame.sample, frame.index, frame.first_of_sentence,
                      out);
    if (out.size() != size || std::memcmp(out.data(), data, 1) != 0 || static_cast<std::uint8_t>(out[1]) != (data[1] & 1) ||
        std::memcmp(out.data() + 2, data + 2, size - 2) != 0)
      __builtin_trap();
  }

  // Encode -> decode: the first 17 bytes choose the header, the rest are weights then audio.
  if (size < 17) return 0;
  std::uint32_t session, index;
  std::int64_t sample;
  std::memcpy(&session, data, 4);
  std::memcpy(&sample, data + 4, 8);
  std::memcpy(&index, data + 12, 4);
  const bool first = (data[16] & 1) != 0;
  const std::size_t rest = size - 17;
  const std::size_t k = std::min<std::size_t>(rest / 8, kLiveMaxWeights);
  const std::size_t n = std::min<std::size_t>((rest - 4 * k) / 2, kLiveMaxAudio);
  std::vector<float> weights(k);
  std::vector<std::int16_t> audio(n);
  if (k != 0) std::memcpy(weights.data(), data + 17, 4 * k);  // an empty vector's data() may be null
  if (n != 0) std::memcpy(audio.data(), data + 17 + 4 * k, 2 * n);
  std::string message;
  encode_live_frame(weights, audio, session, sample, index, first, message);
  LiveFrame back;
  const auto bytes = std::span(reinterpret_cast<const std::uint8_t*>(message.data()), message.size());
  if (decode_live_frame(bytes, back)) __builtin_trap();
  if (back.session != session || back.sample != sample || back.index != index || back.first_of_sentence != first ||
      back.weights.size() != k || back.audio != audio ||
      (k != 0 && std::memcmp(back.weights.data(), weights.data(), 4 * k) != 0))
    __builtin_trap();
  return 0;
}
