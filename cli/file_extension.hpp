#pragma once
// A path's extension in lower case (".glb", ".textgrid"): how the commands pick a format.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace fapcast::cli {

inline std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace fapcast::cli
