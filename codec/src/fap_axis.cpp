#include "fapcast/codec/fap_axis.hpp"

namespace fapcast {

std::optional<Eigen::Vector3d> direction_axis(std::string_view direction) {
  if (direction == "up") return Eigen::Vector3d::UnitY();
  if (direction == "down") return -Eigen::Vector3d::UnitY();
  if (direction == "left") return Eigen::Vector3d::UnitX();
  if (direction == "right") return -Eigen::Vector3d::UnitX();
  if (direction == "forward") return Eigen::Vector3d::UnitZ();
  return std::nullopt;
}

std::optional<Eigen::Vector3d> fap_axis(int number) { return direction_axis(fap_info(number).direction); }

}  // namespace fapcast
