#include "fapcast/serve/live_message.hpp"

#include <bit>
#include <cstring>

namespace fapcast {
namespace {
static_assert(std::endian::native == std::endian::little, "the live frame is written in host order");

template <typename T>
void put(std::string& out, T v) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &v, sizeof(T));
  out.append(bytes, sizeof(T));
}
template <typename T>
T get(std::span<const std::uint8_t> in, std::size_t at) {
  T v;
  std::memcpy(&v, in.data() + at, sizeof(T));
  return v;
}
}  // namespace

void encode_live_frame(std::span<const float> weights, std::span<const std::int16_t> audio, std::uint32_t session,
                       std::int64_t sample, std::uint32_t index, bool first_of_sentence, std::string& out) {
  out.reserve(out.size() + kLiveFrameHeaderBytes + 4 * weights.size() + 2 * audio.size());
  put<std::uint8_t>(out, kLiveFrameType);
  put<std::uint8_t>(out, first_of_sentence ? kLiveFirstOfSentence : 0);
  put<std::uint16_t>(out, static_cast<std::uint16_t>(weights.size()));
  put<std::uint32_t>(out, session);
  put<std::int64_t>(out, sample);
  put<std::uint32_t>(out, static_cast<std::uint32_t>(audio.size()));
  put<std::uint32_t>(out, index);
  // An empty span's data() may be null, which memcpy must not see even for 0 bytes.
  if (!weights.empty()) out.append(reinterpret_cast<const char*>(weights.data()), 4 * weights.size());
  if (!audio.empty()) out.append(reinterpret_cast<const char*>(audio.data()), 2 * audio.size());
}

std::error_code decode_live_frame(std::span<const std::uint8_t> in, LiveFrame& out) {
  if (in.size() < kLiveFrameHeaderBytes || in[0] != kLiveFrameType) return make_error_code(std::errc::invalid_argument);
  const std::size_t k = get<std::uint16_t>(in, 2);
  const std::size_t n = get<std::uint32_t>(in, 16);
  if (k > kLiveMaxWeights || n > kLiveMaxAudio) return make_error_code(std::errc::value_too_large);
  if (in.size() != kLiveFrameHeaderBytes + 4 * k + 2 * n) return make_error_code(std::errc::invalid_argument);
  out.first_of_sentence = (in[1] & kLiveFirstOfSentence) != 0;
  out.session = get<std::uint32_t>(in, 4);
  out.sample = get<std::int64_t>(in, 8);
  out.index = get<std::uint32_t>(in, 20);
  out.weights.resize(k);
  out.audio.resize(n);
  if (k != 0) std::memcpy(out.weights.data(), in.data() + kLiveFrameHeaderBytes, 4 * k);
  if (n != 0) std::memcpy(out.audio.data(), in.data() + kLiveFrameHeaderBytes + 4 * k, 2 * n);
  return {};
}

}  // namespace fapcast
