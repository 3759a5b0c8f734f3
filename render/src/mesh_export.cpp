#include "fapcast/render/mesh_export.hpp"

#include <cstdio>
#include <stdexcept>

#include "fapcast/face/obj_mesh.hpp"
#include "fapcast/core/file_io.hpp"

namespace fapcast {

namespace {
constexpr float kMetresPerCm = 0.01f;
}

MorphAnimation morph_animation_from_cm(const Positions& base_cm,
                                              const PolygonFaces& faces,
                                              const std::vector<Positions>& targets_cm,
                                              std::vector<std::string> target_names,
                                              Eigen::MatrixXf weights, FrameRate rate,
                                              std::string name) {
  MorphAnimation a;
  a.name = std::move(name);
  a.base_positions_m = kMetresPerCm * base_cm;
  a.triangles = triangulate(faces);
  for (const auto& t : targets_cm) a.targets_m.push_back(kMetresPerCm * t);
  a.target_names = std::move(target_names);
  a.weights = std::move(weights);
  a.rate = rate;
  return a;
}

MorphAnimation morph_animation_from_speech(const SpeechBasis& basis, const PolygonFaces& faces,
                                                  Eigen::MatrixXf weights, FrameRate rate, std::string name) {
  const Eigen::Index d = basis.dimension();
  if (d % 3 != 0 || weights.cols() != basis.size() || basis.names().size() != static_cast<std::size_t>(basis.size()))
    throw std::invalid_argument("morph basis mean, directions, names and weights disagree in size");
  const Eigen::Index n = d / 3;
  MorphAnimation a;
  a.name = std::move(name);
  a.base_positions_m = Eigen::Map<const Eigen::Matrix3Xf>(basis.mean().data(), 3, n);
  a.triangles = triangulate(faces);
  for (Eigen::Index k = 0; k < basis.size(); ++k)
    a.targets_m.push_back(Eigen::Map<const Eigen::Matrix3Xf>(basis.direction(k).data(), 3, n));
  a.target_names = basis.names();
  a.weights = std::move(weights);
  a.rate = rate;
  return a;
}

std::size_t write_obj_frames(const MorphAnimation& animation, const std::filesystem::path& dir,
                             int every) {
  std::filesystem::create_directories(dir);
  PolygonFaces faces;
  faces.face_vertices.assign(animation.triangles.data(),
                             animation.triangles.data() + animation.triangles.size());
  for (Eigen::Index t = 1; t <= animation.triangles.cols(); ++t)
    faces.face_starts.push_back(static_cast<std::int32_t>(3 * t));
  std::size_t written = 0;
  for (Eigen::Index f = 0; f < animation.weights.rows(); f += std::max(every, 1)) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06ld.obj", static_cast<long>(f));
    write_file_atomically(
        dir / name, write_obj_mesh(frame_positions(animation, f), faces,
                                          "fapcast frame " + std::to_string(f) + ", metres"));
    ++written;
  }
  return written;
}

}  // namespace fapcast
