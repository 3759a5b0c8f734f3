#pragma once
// Glue between synth's meshes (cm, polygons) and codec's glTF export (metres, triangles): what
// `fapcast expressions -o OUT.glb` and `fapcast say -o OUT.glb` use (a voice's PCA mean is the
// base mesh, its components the targets, its PCA frames the weights).
#include <filesystem>
#include <string>
#include <vector>

#include "fapcast/codec/gltf_export.hpp"
#include "fapcast/face/mesh_types.hpp"
#include "fapcast/synthesis/speech_expression.hpp"

namespace fapcast {

// base_cm: 3 x N; targets_cm: K displacements 3 x N; weights: F x K. Converts cm to metres and
// splits the polygons into triangles.
MorphAnimation morph_animation_from_cm(const Positions& base_cm,
                                              const PolygonFaces& faces,
                                              const std::vector<Positions>& targets_cm,
                                              std::vector<std::string> target_names,
                                              Eigen::MatrixXf weights, FrameRate rate,
                                              std::string name);

// A voice's face as a morph animation (already in metres): the basis mean 1 x 3N (xyz
// interleaved per vertex) is the base mesh, each of its K directions (the k PCA components, then
// an expression's) a morph target named by basis.names, and the F x K weights
// (speech_weights) the animation; faces: the voice's mesh (the ICT face). What
// `fapcast say -o OUT.glb` writes at Voice::kFramesPerSecond. Throws std::invalid_argument when
// the sizes disagree.
MorphAnimation morph_animation_from_speech(const SpeechBasis& basis, const PolygonFaces& faces,
                                                  Eigen::MatrixXf weights, FrameRate rate, std::string name);

// Writes frames 0, every, 2 * every ... of the animation as OBJ files frame_000000.obj ... in
// `dir` (created; each written atomically), positions in metres. Returns the count written.
std::size_t write_obj_frames(const MorphAnimation& animation, const std::filesystem::path& dir,
                             int every = 1);

}  // namespace fapcast
