#include "page_assets.hpp"

#include "fapcast/codec/gltf_export.hpp"
#include "fapcast/core/file_io.hpp"
#include "fapcast/face/face_model.hpp"
#include "fapcast/face/facial_expression.hpp"
#include "fapcast/render/mesh_export.hpp"
#include "fapcast/synthesis/speech_expression.hpp"

#include <algorithm>
#include <stdexcept>

namespace fapcast {

std::optional<std::string> face_glb(const Voice& voice, const std::string& name) {
  const FaceModel& face = ict_face_model();
  if (voice.dimension() != 3 * face.vertex_count()) return std::nullopt;
  SpeechBasis basis(voice);
  for (const Expression e : all_expressions())
    basis.add(expression_direction_m(voice, face, {{e, kMaxExpressionIntensity}, std::nullopt}), std::string(expression_name(e)));
  const MorphAnimation animation = morph_animation_from_speech(
      basis, face.faces, Eigen::MatrixXf(0, basis.size()), {25, 1}, "fapcast serve: " + name);
  return write_glb(animation);
}

PageAssets load_page_assets(const std::filesystem::path& three_dir) {
  PageAssets a;
  a.page_html = std::string(embedded_page_html());
  a.page_script = std::string(embedded_page_script());
  const std::string hint = " (the avatar page's three.js: Debian package libjs-three, or --three-dir)";
  std::error_code ec;
  if (!std::filesystem::is_directory(three_dir, ec))
    throw std::runtime_error(three_dir.string() + ": not a folder" + hint);
  std::size_t total = 0;
  const std::filesystem::path root = std::filesystem::weakly_canonical(three_dir, ec);
  const auto inside = [&](const std::filesystem::path& p) {
    std::error_code e;
    const std::filesystem::path target = std::filesystem::canonical(p, e);
    if (e) return false;
    const auto [r, t] = std::mismatch(root.begin(), root.end(), target.begin(), target.end());
    return r == root.end();
  };
  for (auto it = std::filesystem::recursive_directory_iterator(three_dir, ec); !ec && it != std::filesystem::end(it);
       it.increment(ec)) {
    // A symbolic link to a file inside the folder is served under its own path too: Debian's
    // build/three.module.js (what GLTFLoader imports) is a link to ../three.module.js.
    if (!it->is_regular_file(ec)) continue;
    if (it->is_symlink(ec) && !inside(it->path())) continue;
    // Lexically: relative() would resolve the link and name the file it points to.
    const std::string rel = it->path().lexically_relative(three_dir).generic_string();
    std::string bytes = read_file(it->path(), kMaxThreeBytes);
    total += bytes.size();
    if (total > kMaxThreeBytes)
      throw std::runtime_error(three_dir.string() + ": more than " + std::to_string(kMaxThreeBytes) + " bytes" + hint);
    a.three.emplace(rel, std::move(bytes));
  }
  if (ec) throw std::runtime_error(three_dir.string() + ": " + ec.message() + hint);
  return a;
}

}  // namespace fapcast
