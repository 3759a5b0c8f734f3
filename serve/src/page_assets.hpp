#pragma once
// What the avatar page needs (spec/serve.md, "The avatar page"): the page and its script
// (serve/web/, compiled into the binary), three.js and its GLTFLoader from Debian's libjs-three
// (every file of its folder, read once at start), and each voice's face as a .glb: the voice's PCA mean as the mesh, its k
// components as the first k morph targets, then the six FAP 2 expressions at full intensity (on
// the voice's face) as six more; no animation (the weights arrive live).
#include "fapcast/voice/voice.hpp"

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace fapcast {

struct PageAssets {
  std::string page_html;
  std::string page_script;
  std::map<std::string, std::string> three;     // path under the three.js folder -> its bytes
  // voice name -> its .glb, or nothing for a face not on the ICT topology: made on the first
  // GET /v1/face.glb of the voice (tens of milliseconds, once), so that starting is quick.
  std::map<std::string, std::optional<std::string>> face_glb;
};

// Reads every regular file under `three_dir` (at most kMaxThreeBytes in all), and every symbolic
// link to a file inside it under the link's own path. Throws
// std::runtime_error naming the folder when it is missing or too big, or a file that cannot be read.
inline constexpr std::size_t kMaxThreeBytes = 64u << 20;
PageAssets load_page_assets(const std::filesystem::path& three_dir);

// The voice's face for the page, or nothing when its face is not the ICT topology.
std::optional<std::string> face_glb(const Voice& voice, const std::string& name);

// The page files compiled in (serve/web/).
std::string_view embedded_page_html();
std::string_view embedded_page_script();

}  // namespace fapcast
