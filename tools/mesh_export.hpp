#pragma once
// Glue between synth's meshes (cm, polygons) and codec's glTF export (metres, triangles): what
// `fapcast expressions -o OUT.glb` uses now and `fapcast say -o OUT.glb` will use (a voice's PCA
// mean is the base mesh, its components the targets, its PCA frames the weights).
#include <filesystem>
#include <string>
#include <vector>

#include "fapcast/codec/gltf_export.hpp"
#include "fapcast/synth/mesh_types.hpp"

namespace fapcast::tools {

// base_cm: 3 x N; targets_cm: K displacements 3 x N; weights: F x K. Converts cm to metres and
// splits the polygons into triangles.
codec::MorphAnimation morph_animation_from_cm(const synth::Positions& base_cm,
                                              const synth::PolygonFaces& faces,
                                              const std::vector<synth::Positions>& targets_cm,
                                              std::vector<std::string> target_names,
                                              Eigen::MatrixXf weights, codec::FrameRate rate,
                                              std::string name);

// A voice's PCA as a morph animation (already in metres): mean 1 x 3N (xyz interleaved per
// vertex) is the base mesh, each of the k rows of components 1 x 3N a morph target, and the
// F x k PCA frames the weights; faces: the voice's target mesh (the ICT face). What
// `fapcast say -o OUT.glb` calls with voice.pca_mean(), voice.pca_components() and the
// synthesised frames at Voice::kFramesPerSecond. Throws std::invalid_argument when the sizes
// disagree.
codec::MorphAnimation morph_animation_from_pca(
    const Eigen::Ref<const Eigen::Matrix<float, 1, Eigen::Dynamic>>& mean_m,
    const Eigen::Ref<const Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>& components_m,
    const synth::PolygonFaces& faces, Eigen::MatrixXf pca_frames, codec::FrameRate rate,
    std::string name);

// Writes frames 0, every, 2 * every ... of the animation as OBJ files frame_000000.obj ... in
// `dir` (created; each written atomically), positions in metres. Returns the count written.
std::size_t write_obj_frames(const codec::MorphAnimation& animation, const std::filesystem::path& dir,
                             int every = 1);

}  // namespace fapcast::tools
