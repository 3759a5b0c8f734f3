#pragma once
// The axis along which a FAP moves its feature point, in face axes (x = the face's own left,
// y up, z forward): the table's "direction" column as a unit vector.
#include "fapcast/codec/fap_table.hpp"

#include <Eigen/Core>

#include <optional>
#include <string_view>

namespace fapcast {

// "up" +y, "down" -y, "left" +x, "right" -x, "forward" +z; nullopt for directions that are not a
// translation (rotations of eyeballs and head, "growing" pupils, "concave-up" tongue roll).
std::optional<Eigen::Vector3d> direction_axis(std::string_view direction);

// The axis of FAP `number` (1..68): direction_axis of its row.
std::optional<Eigen::Vector3d> fap_axis(int number);

}  // namespace fapcast
