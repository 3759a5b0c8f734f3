#pragma once
// Morph targets kept as OBJ files (one full mesh per target, same topology as the neutral mesh):
// adapting a folder of them from a generic face to a specific one, and the six FAP 2 expressions
// written as such targets.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "fapcast/core/input_error.hpp"
#include "fapcast/face/face_model.hpp"

namespace fapcast {

// Receives one output file: its name (e.g. "jawOpen.obj") and its bytes.
using WriteFile = std::function<void(const std::string& name, std::string_view bytes)>;

// The *.obj files directly in `dir`, sorted by name; throws InputError (line 0) when `dir` is
// not a directory ("no-target-folder") or holds no .obj file ("no-targets").
std::vector<std::filesystem::path> list_obj_targets(const std::filesystem::path& dir);

// Reads the generic and specific neutral meshes and every target in `targets_dir`, and writes
// each target adapted to the specific face: specific + FaceAdaptation(target - generic), with the
// specific mesh's faces, under the target's file name. Throws InputError for a bad OBJ
// (file:line: rule) or a mesh whose topology differs from the generic one ("topology-mismatch").
// Returns the number of targets written.
std::size_t adapt_obj_targets(const std::filesystem::path& generic_file,
                              const std::filesystem::path& specific_file,
                              const std::filesystem::path& targets_dir, const WriteFile& write);

// The six FAP 2 expressions at `intensity` (0..63) on `face`'s neutral mesh, one OBJ per
// expression ("joy.obj" ...), in the face's unit (cm for ICT).
void write_expression_targets(const FaceModel& face, int intensity, const WriteFile& write);

}  // namespace fapcast
