#include "page_assets.hpp"

#include "fapcast/codec/gltf_export.hpp"
#include "fapcast/core/file_io.hpp"
#include "fapcast/face/face_model.hpp"
#include "fapcast/face/facial_expression.hpp"
#include "fapcast/render/mesh_export.hpp"
#include "fapcast/synthesis/speech_expression.hpp"

#include <stdexcept>

namespace fapcast {

std::optional<std::string> face_glb(const Voice& voice, const std::string& name) {
  const FaceModel& face = ict_face_model();
  if (voice.dimension() != 3 * face.vertex_count()) return std::nullopt;
  SpeechBasis basis = speech_basis(voice);
  const Eigen::Index k = basis.components.rows();
  basis.components.conservativeResize(k + static_cast<Eigen::Index>(kExpressionCount), Eigen::NoChange);
  Eigen::Index row = k;
  for (const Expression e : all_expressions()) {
    basis.components.row(row++) = expression_direction_m(voice, face, {{e, kMaxExpressionIntensity}, std::nullopt});
    basis.names.emplace_back(expression_name(e));
  }
  const MorphAnimation animation = morph_animation_from_speech(
      basis, face.faces, Eigen::MatrixXf(0, basis.components.rows()), {25, 1}, "fapcast serve: " + name);
  return write_glb(animation);
}

PageAssets load_page_assets(const std::filesystem::path& three_dir, const std::map<std::string, Voice>& voices,
                            const std::function<void(std::string_view)>& log) {
  PageAssets a;
  a.page_html = std::string(embedded_page_html());
  a.page_script = std::string(embedded_page_script());
  const auto three = [&](const char* file) {
    try {
      return read_file(three_dir / file, 16 << 20);
    } catch (const std::exception& e) {
      throw std::runtime_error(std::string(e.what()) + " (the avatar page's three.js: Debian package libjs-three, or three_dir)");
    }
  };
  a.three_js = three("build/three.min.js");
  a.gltf_loader_js = three("examples/js/loaders/GLTFLoader.js");
  for (const auto& [name, voice] : voices) {
    if (auto glb = face_glb(voice, name)) a.face_glb.emplace(name, std::move(*glb));
    else if (log) log("voice '" + name + "': its face is not the ICT topology: the page cannot show it (RTP only)");
  }
  return a;
}

}  // namespace fapcast
