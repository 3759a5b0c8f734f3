#include "fapcast/rig/glb_builder.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace fapcast {

GlbBuilder::GlbBuilder(nlohmann::json json, std::vector<std::uint8_t> bin) : json_(std::move(json)), bin_(std::move(bin)) {}

int GlbBuilder::add_float_accessor(std::span<const float> values, const char* type, bool with_bounds) {
  const int components = std::strcmp(type, "SCALAR") == 0 ? 1 : std::strcmp(type, "VEC3") == 0 ? 3 : 0;
  if (components == 0 || values.size() % static_cast<std::size_t>(components) != 0 || values.empty())
    throw std::invalid_argument("GlbBuilder: accessor type must be SCALAR or VEC3, with whole elements");
  bin_.resize((bin_.size() + 3) / 4 * 4, 0);
  const std::size_t offset = bin_.size();
  bin_.resize(offset + values.size() * sizeof(float));
  std::memcpy(bin_.data() + offset, values.data(), values.size() * sizeof(float));
  auto& views = json_["bufferViews"];
  if (views.is_null()) views = nlohmann::json::array();
  views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", values.size() * sizeof(float)}});
  nlohmann::json accessor = {{"bufferView", views.size() - 1},
                             {"componentType", 5126},
                             {"count", values.size() / static_cast<std::size_t>(components)},
                             {"type", type}};
  if (with_bounds) {
    std::vector<float> lo(static_cast<std::size_t>(components), std::numeric_limits<float>::max());
    std::vector<float> hi(static_cast<std::size_t>(components), std::numeric_limits<float>::lowest());
    for (std::size_t i = 0; i < values.size(); ++i) {
      const auto c = i % static_cast<std::size_t>(components);
      lo[c] = std::min(lo[c], values[i]);
      hi[c] = std::max(hi[c], values[i]);
    }
    accessor["min"] = lo;
    accessor["max"] = hi;
  }
  auto& accessors = json_["accessors"];
  if (accessors.is_null()) accessors = nlohmann::json::array();
  accessors.push_back(accessor);
  return static_cast<int>(accessors.size() - 1);
}

std::string GlbBuilder::finish() {
  bin_.resize((bin_.size() + 3) / 4 * 4, 0);
  auto& buffers = json_["buffers"];
  if (buffers.is_null() || buffers.empty()) buffers = nlohmann::json::array({nlohmann::json::object()});
  buffers[0]["byteLength"] = bin_.size();
  std::string text = json_.dump();
  text.resize((text.size() + 3) / 4 * 4, ' ');
  const std::size_t total = 12 + 8 + text.size() + (bin_.empty() ? 0 : 8 + bin_.size());
  if (total > std::numeric_limits<std::uint32_t>::max()) throw std::length_error("GlbBuilder: file over 4 GiB");
  std::string out;
  out.reserve(total);
  auto put32 = [&](std::uint32_t v) { for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>(v >> (8 * i))); };
  out += "glTF";
  put32(2);
  put32(static_cast<std::uint32_t>(total));
  put32(static_cast<std::uint32_t>(text.size()));
  out += "JSON";
  out += text;
  if (!bin_.empty()) {
    put32(static_cast<std::uint32_t>(bin_.size()));
    out.append("BIN\0", 4);
    out.append(reinterpret_cast<const char*>(bin_.data()), bin_.size());
  }
  return out;
}

}  // namespace fapcast
