#include "default_voice_key.hpp"

#include <cstdio>
#include <string_view>

#include "fapcast/core/crc32.hpp"

namespace fapcast::cli {
namespace {

// Fields are written as text (floats with 9 significant digits: exact for float32), one per
// line, so the key does not depend on struct layout or endianness.
class KeyText {
 public:
  KeyText& operator<<(std::string_view s) {
    text_.append(s);
    text_.push_back('\n');
    return *this;
  }
  KeyText& operator<<(double x) {
    char b[32];
    std::snprintf(b, sizeof b, "%.9g", x);
    return *this << std::string_view(b);
  }
  KeyText& operator<<(std::uint64_t x) { return *this << std::string_view(std::to_string(x)); }
  const std::string& text() const { return text_; }

 private:
  std::string text_;
};

}  // namespace

std::string default_voice_key(std::uint64_t seed, std::span<const PhoneChannelTarget> articulation,
                              std::span<const ChannelShapeRow> shapes,
                              std::span<const PrototypeShapeWeight> details) {
  KeyText k;
  k << std::uint64_t{kDefaultVoiceRecipe} << seed << kSourcePrototypeRule << kTargetPrototypeRule;
  for (const PhoneChannelTarget& r : articulation)
    k << r.phone << channel_name(r.channel) << double{r.target} << double{r.dominance.alpha}
      << double{r.dominance.theta_before_per_s} << double{r.dominance.theta_after_per_s} << double{r.dominance.c};
  for (const ChannelShapeRow& r : shapes)
    k << channel_name(r.channel) << r.shape << double{r.weight}
      << (r.scale_by ? channel_name(*r.scale_by) : std::string_view("-")) << std::uint64_t{r.gated};
  for (const PrototypeShapeWeight& r : details) k << viseme_class_name(r.viseme) << r.shape << double{r.weight};
  const std::string& text = k.text();
  const std::uint32_t crc = crc32(std::as_bytes(std::span(text.data(), text.size())));
  char hex[9];
  std::snprintf(hex, sizeof hex, "%08x", static_cast<unsigned>(crc));
  return hex;
}

std::string default_voice_key(std::uint64_t seed) {
  return default_voice_key(seed, articulation_table(), channel_shape_table(), target_prototype_details());
}

}  // namespace fapcast::cli
