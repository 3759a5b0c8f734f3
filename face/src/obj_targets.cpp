#include "fapcast/face/obj_targets.hpp"

#include <algorithm>
#include <system_error>

#include "fapcast/core/input_error.hpp"
#include "fapcast/face/face_adaptation.hpp"
#include "fapcast/face/facial_expression.hpp"
#include "fapcast/face/obj_mesh.hpp"

namespace fapcast {

std::vector<std::filesystem::path> list_obj_targets(const std::filesystem::path& dir) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    throw InputError::in_file(dir.string(), 0, "no-target-folder", "not a directory");
  std::vector<std::filesystem::path> out;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().extension() == ".obj") out.push_back(entry.path());
  if (out.empty()) throw InputError::in_file(dir.string(), 0, "no-targets", "no .obj file in the folder");
  std::sort(out.begin(), out.end());
  return out;
}

std::size_t adapt_obj_targets(const std::filesystem::path& generic_file,
                              const std::filesystem::path& specific_file,
                              const std::filesystem::path& targets_dir, const WriteFile& write) {
  const ObjMesh generic = read_obj_mesh(generic_file);
  const ObjMesh specific = read_obj_mesh(specific_file);
  require_same_topology(generic, generic_file, specific, specific_file);
  // Read and check every target before writing any, so a bad one leaves no partial output.
  const auto files = list_obj_targets(targets_dir);
  std::vector<Positions> displacements;
  for (const auto& file : files) {
    const ObjMesh target = read_obj_mesh(file);
    require_same_topology(generic, generic_file, target, file);
    displacements.push_back(target.vertices - generic.vertices);
  }
  const FaceAdaptation adaptation(generic.vertices, specific.vertices, generic.faces);
  for (std::size_t i = 0; i < files.size(); ++i) {
    const Positions adapted = specific.vertices + adaptation.adapt(displacements[i]);
    const std::string comment = "fapcast adapt: " + files[i].filename().string() + " on " +
                                specific_file.filename().string();
    write(files[i].filename().string(), write_obj_mesh(adapted, specific.faces, comment));
  }
  return files.size();
}

void write_expression_targets(const FaceModel& face, int intensity, const WriteFile& write) {
  for (const Expression e : all_expressions()) {
    const FacialExpression setting{e, intensity};
    const Positions mesh = face.neutral_cm + expression_displacement(face, setting);
    const std::string name(expression_name(e));
    write(name + ".obj", write_obj_mesh(mesh, face.faces,
                                        "fapcast FAP 2 expression " + name + " at intensity " +
                                            std::to_string(intensity) + " of 63 (spec/expressions.tsv), cm"));
  }
}

}  // namespace fapcast
