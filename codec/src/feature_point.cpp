#include "fapcast/codec/feature_point.hpp"

#include <charconv>

namespace fapcast {

std::string FeaturePoint::label() const {
  return std::to_string(group) + "." + std::to_string(index);
}

std::ostream& operator<<(std::ostream& out, FeaturePoint fp) { return out << fp.label(); }

std::optional<FeaturePoint> parse_feature_point(std::string_view label) {
  const auto dot = label.find('.');
  if (dot == std::string_view::npos || dot == 0 || dot + 1 == label.size()) return std::nullopt;
  auto number = [](std::string_view digits, int lo, int hi) -> std::optional<int> {
    int v = 0;
    if (digits.empty() || digits.size() > 2) return std::nullopt;
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
    if (ec != std::errc{} || end != digits.data() + digits.size() || v < lo || v > hi)
      return std::nullopt;
    return v;
  };
  const auto group = number(label.substr(0, dot), 2, 11);
  const auto index = number(label.substr(dot + 1), 1, 99);
  if (!group || !index) return std::nullopt;
  return FeaturePoint{static_cast<std::uint8_t>(*group), static_cast<std::uint8_t>(*index)};
}

}  // namespace fapcast
