#include "fapcast/render/rasteriser.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace fapcast {
namespace {

constexpr std::uint8_t kBackground = 40;
const Eigen::Vector3f kSkin(0.93f, 0.76f, 0.65f);

}  // namespace

ViewBox whole_view(const Eigen::Matrix3Xf& positions) {
  if (positions.cols() == 0) throw std::invalid_argument("render: no vertices");
  return {positions.topRows<2>().rowwise().minCoeff(), positions.topRows<2>().rowwise().maxCoeff()};
}

ViewBox moving_view(const Eigen::Matrix3Xf& positions, const std::vector<Eigen::Matrix3Xf>& targets,
                    float fraction) {
  Eigen::VectorXf motion = Eigen::VectorXf::Zero(positions.cols());
  for (const auto& t : targets) motion = motion.cwiseMax(t.colwise().norm().transpose());
  const float largest = motion.size() ? motion.maxCoeff() : 0.0f;
  if (!(largest > 0)) return whole_view(positions);
  ViewBox box{Eigen::Vector2f::Constant(std::numeric_limits<float>::max()),
              Eigen::Vector2f::Constant(std::numeric_limits<float>::lowest())};
  for (Eigen::Index i = 0; i < positions.cols(); ++i)
    if (motion(i) >= fraction * largest) {
      box.min = box.min.cwiseMin(positions.col(i).head<2>());
      box.max = box.max.cwiseMax(positions.col(i).head<2>());
    }
  return box;
}

Image render_front(const Eigen::Matrix3Xf& positions, const Eigen::Matrix3Xi& triangles,
                   const ViewBox& view, int width) {
  if (width < 8 || width > 8192) throw std::invalid_argument("render: width must be 8..8192 pixels");
  const Eigen::Vector2f pad = 0.1f * (view.max - view.min).cwiseMax(1e-6f);
  const Eigen::Vector2f lo = view.min - pad, hi = view.max + pad;
  const float scale = static_cast<float>(width) / (hi.x() - lo.x());  // pixels per unit
  const int height = std::clamp(static_cast<int>(std::lround((hi.y() - lo.y()) * scale)), 8, 8192);
  Image image{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height * 3, kBackground)};
  std::vector<float> depth(static_cast<std::size_t>(width) * height, std::numeric_limits<float>::lowest());
  const Eigen::Vector3f light = Eigen::Vector3f(-0.4f, 0.5f, 1.0f).normalized();

  // Screen coordinates: x to the right, y down from the top row; z towards the viewer.
  const auto screen = [&](int v) {
    const Eigen::Vector3f p = positions.col(v);
    return Eigen::Vector3f((p.x() - lo.x()) * scale, (hi.y() - p.y()) * scale, p.z());
  };
  for (Eigen::Index t = 0; t < triangles.cols(); ++t) {
    const Eigen::Vector3f a = screen(triangles(0, t)), b = screen(triangles(1, t)), c = screen(triangles(2, t));
    const Eigen::Vector3f normal = (positions.col(triangles(1, t)) - positions.col(triangles(0, t)))
                                       .cross(positions.col(triangles(2, t)) - positions.col(triangles(0, t)));
    const float length = normal.norm();
    if (!(length > 0)) continue;
    const float lambert = std::abs(normal.dot(light)) / length;  // both sides lit
    const Eigen::Vector3f colour = 255.0f * (0.15f + 0.85f * lambert) * kSkin;
    const float area = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
    if (std::abs(area) < 1e-12f) continue;
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x(), b.x(), c.x()}))));
    const int x1 = std::min(width - 1, static_cast<int>(std::ceil(std::max({a.x(), b.x(), c.x()}))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y(), b.y(), c.y()}))));
    const int y1 = std::min(height - 1, static_cast<int>(std::ceil(std::max({a.y(), b.y(), c.y()}))));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const float px = static_cast<float>(x) + 0.5f, py = static_cast<float>(y) + 0.5f;
        // Barycentric weights by edge functions; the sign of `area` fixes the winding.
        const float w0 = ((b.x() - px) * (c.y() - py) - (b.y() - py) * (c.x() - px)) / area;
        const float w1 = ((c.x() - px) * (a.y() - py) - (c.y() - py) * (a.x() - px)) / area;
        const float w2 = 1.0f - w0 - w1;
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        const float z = w0 * a.z() + w1 * b.z() + w2 * c.z();
        const auto i = static_cast<std::size_t>(y) * width + x;
        if (z <= depth[i]) continue;
        depth[i] = z;
        for (int k = 0; k < 3; ++k)
          image.rgb[3 * i + k] = static_cast<std::uint8_t>(std::clamp(colour(k), 0.0f, 255.0f));
      }
  }
  return image;
}

std::string to_ppm(const Image& image) {
  std::string out = "P6\n";
  out += std::to_string(image.width);
  out += ' ';
  out += std::to_string(image.height);
  out += "\n255\n";
  out.append(reinterpret_cast<const char*>(image.rgb.data()), image.rgb.size());
  return out;
}

std::size_t covered_pixels(const Image& image) {
  std::size_t n = 0;
  for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3)
    if (image.rgb[i] != kBackground || image.rgb[i + 1] != kBackground || image.rgb[i + 2] != kBackground) ++n;
  return n;
}

}  // namespace fapcast
