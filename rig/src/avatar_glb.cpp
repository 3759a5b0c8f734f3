#include "fapcast/rig/avatar_glb.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <set>
#include <unordered_map>

#include "fapcast/core/input_error.hpp"
#include "fapcast/rig/glb_builder.hpp"

namespace fapcast {

namespace {

[[noreturn]] void fail(const std::string& source, std::optional<std::uint64_t> offset, const char* rule,
                       const std::string& detail) {
  throw InputError({source, std::nullopt, offset}, rule, detail);
}

std::uint32_t le32(std::string_view b, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(b[at + static_cast<std::size_t>(i)]);
  return v;
}

const nlohmann::json* member(const nlohmann::json& j, const char* key) {
  if (!j.is_object()) return nullptr;
  const auto it = j.find(key);
  return it == j.end() ? nullptr : &*it;
}

std::int64_t index_of(const nlohmann::json& j, const char* key, std::int64_t size) {
  const nlohmann::json* v = member(j, key);
  if (!v || !v->is_number_integer()) return -1;
  const auto i = v->get<std::int64_t>();
  return i >= 0 && i < size ? i : -2;
}

struct Reader {
  const Avatar& a;
  const std::string& source;

  [[noreturn]] void bad_accessor(std::int64_t index, const std::string& why) const {
    fail(source, std::nullopt, "gltf-accessor", "accessor " + std::to_string(index) + ": " + why);
  }

  // The element count of an accessor, after checking it is a valid, in-bounds accessor on the BIN
  // chunk with `components` components of an allowed type.
  std::uint64_t count(std::int64_t index) const {
    const auto& accessors = a.json.at("accessors");
    return accessors.at(static_cast<std::size_t>(index)).value("count", std::uint64_t{0});
  }

  std::vector<std::uint32_t> indices(std::int64_t index, std::uint64_t vertex_count) const {
    const nlohmann::json* accessors = member(a.json, "accessors");
    if (!accessors || !accessors->is_array() || index < 0 || index >= static_cast<std::int64_t>(accessors->size()))
      bad_accessor(index, "no such accessor");
    const auto& acc = (*accessors)[static_cast<std::size_t>(index)];
    if (member(acc, "sparse")) bad_accessor(index, "sparse index accessors are not supported");
    if (acc.value("type", std::string()) != "SCALAR") bad_accessor(index, "indices must be SCALAR");
    const int component = acc.value("componentType", 0);
    const std::size_t size = component == 5121 ? 1 : component == 5123 ? 2 : component == 5125 ? 4 : 0;
    if (size == 0) bad_accessor(index, "indices must be unsigned byte, short or int (componentType " + std::to_string(component) + ")");
    const std::uint64_t n = acc.value("count", std::uint64_t{0});
    const nlohmann::json* views = member(a.json, "bufferViews");
    const std::int64_t v = views && views->is_array() ? index_of(acc, "bufferView", static_cast<std::int64_t>(views->size())) : -1;
    if (v < 0) bad_accessor(index, "no buffer view");
    const auto& view = (*views)[static_cast<std::size_t>(v)];
    if (view.value("buffer", -1) != 0) bad_accessor(index, "buffer view " + std::to_string(v) + " is not on the GLB's BIN chunk");
    const std::uint64_t view_offset = view.value("byteOffset", std::uint64_t{0});
    const std::uint64_t view_length = view.value("byteLength", std::uint64_t{0});
    const std::uint64_t stride = view.value("byteStride", std::uint64_t{size});
    const std::uint64_t offset = acc.value("byteOffset", std::uint64_t{0});
    if (stride < size || view_offset > a.bin.size() || view_length > a.bin.size() - view_offset ||
        (n > 0 && (offset > view_length || (n - 1) > (view_length - offset - std::min<std::uint64_t>(size, view_length - offset)) / stride ||
                   offset + (n - 1) * stride + size > view_length)))
      bad_accessor(index, "runs past its buffer view or the BIN chunk");
    std::vector<std::uint32_t> out(static_cast<std::size_t>(n));
    const std::uint8_t* base = a.bin.data() + view_offset + offset;
    for (std::uint64_t i = 0; i < n; ++i) {
      const std::uint8_t* p = base + i * stride;
      std::uint32_t value = 0;
      for (std::size_t b = size; b-- > 0;) value = (value << 8) | p[b];
      if (value >= vertex_count)
        fail(source, std::nullopt, "gltf-indices", "accessor " + std::to_string(index) + " index " + std::to_string(i) + " is " +
                                                   std::to_string(value) + ", past the " + std::to_string(vertex_count) + " vertices");
      out[static_cast<std::size_t>(i)] = value;
    }
    return out;
  }
};

}  // namespace

Avatar read_avatar(std::string_view b, const std::string& source, const AvatarLimits& limits) {
  if (b.size() > limits.max_bytes)
    fail(source, 0, "avatar-too-large", std::to_string(b.size()) + " bytes, more than " + std::to_string(limits.max_bytes));
  // GLB container: header, a JSON chunk, optionally a BIN chunk ending the file.
  if (b.size() < 20 || b.substr(0, 4) != "glTF") fail(source, 0, "glb-container", "not a GLB file (no \"glTF\" magic)");
  if (le32(b, 4) != 2) fail(source, 4, "glb-container", "version " + std::to_string(le32(b, 4)) + ", want 2");
  if (le32(b, 8) != b.size()) fail(source, 8, "glb-container", "header length " + std::to_string(le32(b, 8)) + " but the file has " + std::to_string(b.size()) + " bytes");
  const std::uint32_t json_length = le32(b, 12);
  if (b.substr(16, 4) != "JSON") fail(source, 16, "glb-container", "first chunk is not JSON");
  if (json_length % 4 != 0 || json_length > b.size() - 20) fail(source, 12, "glb-container", "JSON chunk length " + std::to_string(json_length) + " is not 4-aligned inside the file");
  Avatar a;
  a.source = source;
  const std::size_t bin_at = 20 + json_length;
  if (bin_at < b.size()) {
    if (b.size() - bin_at < 8 || b.substr(bin_at + 4, 4) != std::string_view("BIN\0", 4))
      fail(source, bin_at, "glb-container", "second chunk is not BIN");
    const std::uint32_t bin_length = le32(b, bin_at);
    if (bin_length != b.size() - bin_at - 8) fail(source, bin_at, "glb-container", "BIN chunk length " + std::to_string(bin_length) + " does not end the file");
    a.bin.assign(reinterpret_cast<const std::uint8_t*>(b.data()) + bin_at + 8, reinterpret_cast<const std::uint8_t*>(b.data()) + b.size());
  }
  try {
    a.json = nlohmann::json::parse(b.substr(20, json_length));
  } catch (const nlohmann::json::parse_error& e) {
    fail(source, 20 + e.byte - (e.byte > 0 ? 1 : 0), "glb-syntax", e.what());
  } catch (const nlohmann::json::exception& e) {  // a number out of range (1e523), ...: no byte given
    fail(source, 20, "glb-syntax", e.what());
  }
  if (!a.json.is_object()) fail(source, 20, "glb-syntax", "the JSON chunk is not an object");
  if (const nlohmann::json* required = member(a.json, "extensionsRequired"); required && required->is_array())
    for (const auto& e : *required)
      if (e == "KHR_draco_mesh_compression" || e == "EXT_meshopt_compression" || e == "KHR_meshopt_compression")
        fail(source, std::nullopt, "avatar-compressed", "requires " + e.get<std::string>() + " (decompress it first, e.g. gltf-transform)");
  if (const nlohmann::json* buffers = member(a.json, "buffers"); buffers && buffers->is_array() && !buffers->empty() && member((*buffers)[0], "uri"))
    fail(source, std::nullopt, "glb-container", "buffer 0 is an external file, not the GLB's BIN chunk");
  const nlohmann::json* meshes = member(a.json, "meshes");
  const nlohmann::json* accessors = member(a.json, "accessors");
  const std::int64_t accessor_count = accessors && accessors->is_array() ? static_cast<std::int64_t>(accessors->size()) : 0;
  Reader reader{a, source};
  std::uint64_t vertices = 0;
  if (meshes && meshes->is_array())
    for (std::size_t m = 0; m < meshes->size(); ++m) {
      const auto& mesh = (*meshes)[m];
      const nlohmann::json* primitives = member(mesh, "primitives");
      if (!primitives || !primitives->is_array()) continue;
      std::size_t target_count = 0;
      bool morphed = false;
      for (const auto& p : *primitives) {
        const nlohmann::json* targets = member(p, "targets");
        if (!targets || !targets->is_array() || targets->empty()) continue;
        if (morphed && targets->size() != target_count)
          fail(source, std::nullopt, "gltf-target", "mesh " + std::to_string(m) + ": primitives have different target counts");
        morphed = true;
        target_count = targets->size();
      }
      if (!morphed) continue;
      const std::string name = mesh.value("name", "mesh " + std::to_string(m));
      if (target_count > limits.max_targets_per_mesh)
        fail(source, std::nullopt, "avatar-too-large", name + ": " + std::to_string(target_count) + " morph targets, more than " + std::to_string(limits.max_targets_per_mesh));
      AvatarMesh am;
      am.mesh = static_cast<int>(m);
      am.name = name;
      const nlohmann::json* extras = member(mesh, "extras");
      const nlohmann::json* names = extras ? member(*extras, "targetNames") : nullptr;
      if (!names || !names->is_array() || names->size() != target_count ||
          !std::all_of(names->begin(), names->end(), [](const nlohmann::json& n) { return n.is_string() && !n.get<std::string>().empty(); }))
        fail(source, std::nullopt, "avatar-unnamed-targets", name + ": " + std::to_string(target_count) +
                                                                 " morph targets but no mesh.extras.targetNames naming each");
      for (const auto& n : *names) am.targets.push_back(n.get<std::string>());
      am.default_weights.assign(target_count, 0.0f);
      if (const nlohmann::json* w = member(mesh, "weights"); w && w->is_array() && w->size() == target_count)
        for (std::size_t t = 0; t < target_count; ++t)
          if ((*w)[t].is_number()) am.default_weights[t] = (*w)[t].get<float>();
      for (const auto& p : *primitives) {
        const nlohmann::json* attributes = member(p, "attributes");
        const std::int64_t position = attributes ? index_of(*attributes, "POSITION", accessor_count) : -1;
        if (position < 0) fail(source, std::nullopt, "gltf-position", name + ": a primitive has no valid POSITION accessor");
        const std::uint64_t n = reader.count(position);
        vertices += n;
        if (vertices > limits.max_vertices)
          fail(source, std::nullopt, "avatar-too-large", "more than " + std::to_string(limits.max_vertices) + " morphed vertices");
        if (p.value("mode", 4) != 4 || !member(p, "indices")) continue;  // manifold check on indexed triangles
        const std::vector<std::uint32_t> idx = reader.indices(p["indices"].is_number_integer() ? p["indices"].get<std::int64_t>() : -1, n);
        if (idx.size() % 3 != 0) fail(source, std::nullopt, "gltf-indices", name + ": " + std::to_string(idx.size()) + " indices, not whole triangles");
        std::unordered_map<std::uint64_t, int> edges;
        edges.reserve(idx.size());
        for (std::size_t t = 0; t + 2 < idx.size(); t += 3)
          for (int e = 0; e < 3; ++e) {
            std::uint32_t u = idx[t + static_cast<std::size_t>(e)], v = idx[t + static_cast<std::size_t>((e + 1) % 3)];
            if (u == v) continue;  // degenerate triangle side
            if (u > v) std::swap(u, v);
            if (++edges[(std::uint64_t{u} << 32) | v] == 3)
              fail(source, std::nullopt, "avatar-non-manifold", name + ": the edge between vertices " + std::to_string(u) + " and " +
                                                                    std::to_string(v) + " belongs to more than two triangles (triangle " +
                                                                    std::to_string(t / 3) + ")");
          }
      }
      a.meshes.push_back(std::move(am));
    }
  if (a.meshes.empty()) fail(source, std::nullopt, "avatar-no-morph-targets", "no mesh has morph targets: nothing for a rig to drive");
  if (const nlohmann::json* nodes = member(a.json, "nodes"); nodes && nodes->is_array())
    for (std::size_t i = 0; i < nodes->size(); ++i) {
      const std::int64_t m = index_of((*nodes)[i], "mesh", meshes ? static_cast<std::int64_t>(meshes->size()) : 0);
      for (AvatarMesh& am : a.meshes)
        if (am.mesh == m) am.nodes.push_back(static_cast<int>(i));
    }
  return a;
}

AvatarAnimation animate_avatar(const Avatar& avatar, std::span<const std::string> names, const Eigen::MatrixXf& weights,
                               FrameRate rate, const std::string& animation_name) {
  if (!rate.valid() || weights.rows() < 1 || weights.cols() != static_cast<Eigen::Index>(names.size()))
    throw std::invalid_argument("animate_avatar: want a rate and frames x names weights");
  std::map<std::string, Eigen::Index, std::less<>> column;
  for (std::size_t j = 0; j < names.size(); ++j) column.emplace(names[j], static_cast<Eigen::Index>(j));
  AvatarAnimation out;
  std::set<std::string> driven, unknown;
  GlbBuilder glb(avatar.json, avatar.bin);
  const Eigen::Index frames = weights.rows();
  std::vector<float> times(static_cast<std::size_t>(frames));
  for (Eigen::Index f = 0; f < frames; ++f) times[static_cast<std::size_t>(f)] = static_cast<float>(static_cast<double>(f) * rate.denominator / rate.numerator);
  int input = -1;
  nlohmann::json samplers = nlohmann::json::array(), channels = nlohmann::json::array();
  for (const AvatarMesh& m : avatar.meshes) {
    std::vector<Eigen::Index> source(m.targets.size(), -1);
    bool any = false;
    for (std::size_t t = 0; t < m.targets.size(); ++t) {
      const auto it = column.find(m.targets[t]);
      if (it != column.end()) { source[t] = it->second; driven.insert(m.targets[t]); any = true; }
      else unknown.insert(m.targets[t]);
    }
    if (!any || m.nodes.empty()) continue;
    if (input < 0) input = glb.add_float_accessor(times, "SCALAR", true);
    std::vector<float> values(static_cast<std::size_t>(frames) * m.targets.size());
    for (Eigen::Index f = 0; f < frames; ++f)
      for (std::size_t t = 0; t < m.targets.size(); ++t)
        values[static_cast<std::size_t>(f) * m.targets.size() + t] = source[t] >= 0 ? weights(f, source[t]) : m.default_weights[t];
    const int output = glb.add_float_accessor(values, "SCALAR", false);
    samplers.push_back({{"input", input}, {"output", output}, {"interpolation", "LINEAR"}});
    for (int node : m.nodes) channels.push_back({{"sampler", samplers.size() - 1}, {"target", {{"node", node}, {"path", "weights"}}}});
  }
  if (driven.empty()) {
    std::string expected;
    for (std::size_t j = 0; j < names.size() && j < 4; ++j) expected += (j ? ", " : "") + names[j];
    fail(avatar.source, std::nullopt, "avatar-no-known-targets",
         "none of the avatar's morph targets is one the rig drives (e.g. " + expected + "; the avatar has " +
             (avatar.meshes.front().targets.empty() ? std::string("none") : avatar.meshes.front().targets.front()) + ", ...)");
  }
  for (const std::string& d : driven) unknown.erase(d);
  auto& animations = glb.json()["animations"];
  if (animations.is_null()) animations = nlohmann::json::array();
  animations.push_back({{"name", animation_name}, {"samplers", samplers}, {"channels", channels}});
  out.bytes = glb.finish();
  out.driven.assign(driven.begin(), driven.end());
  out.unknown.assign(unknown.begin(), unknown.end());
  return out;
}

}  // namespace fapcast
