#pragma once
// MPEG-4 feature-point labels ("2.1" = chin/jaw tip, "8.3" = left outer lip corner ...).
#include <cstdint>
#include <compare>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>

namespace fapcast {

// A feature-point label: group.index, e.g. {2, 1} for 2.1. Groups 2-11 are defined by the
// standard; index starts at 1. Comparable and printable ("2.1").
struct FeaturePoint {
  std::uint8_t group = 0;
  std::uint8_t index = 0;

  auto operator<=>(const FeaturePoint&) const = default;
  std::string label() const;  // "2.1"
};

std::ostream& operator<<(std::ostream& out, FeaturePoint fp);

// Parses "2.1"; nullopt when the text is not two positive integers joined by one dot,
// group in 2..11 and index in 1..99.
std::optional<FeaturePoint> parse_feature_point(std::string_view label);

}  // namespace fapcast
