#pragma once
// A small headless rasteriser so a person can look at an animation without a GPU or a viewer:
// flat Lambert shading, a z-buffer, an orthographic front view (looking down -z, +y up).
// Not a stage of the pipeline: a tool for looking at its output (`fapcast render`).
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace fapcast {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // row-major from the top, 3 bytes per pixel
  bool operator==(const Image&) const = default;
};

// The part of the xy plane the view shows (scene units, before padding).
struct ViewBox {
  Eigen::Vector2f min, max;
};

// The xy bounding box of every vertex.
ViewBox whole_view(const Eigen::Matrix3Xf& positions);
// The xy bounding box of the vertices that move at least `fraction` of the largest motion in
// any of `targets` (3 x N displacements each): the mouth, for speech targets.
ViewBox moving_view(const Eigen::Matrix3Xf& positions, const std::vector<Eigen::Matrix3Xf>& targets,
                    float fraction = 0.2f);

// Renders the triangles (3 x T indices into positions) to an image `width` pixels wide whose
// height follows the box's aspect (padded by 10 % each side). Background dark grey; surfaces
// lit from the front-upper-left, both sides shaded.
Image render_front(const Eigen::Matrix3Xf& positions, const Eigen::Matrix3Xi& triangles,
                   const ViewBox& box, int width);

// Binary PPM (P6) bytes.
std::string to_ppm(const Image& image);
// Pixels that are not background.
std::size_t covered_pixels(const Image& image);

}  // namespace fapcast
