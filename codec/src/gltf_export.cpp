#include "fapcast/codec/gltf_export.hpp"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "fapcast/core/input_error.hpp"

namespace fapcast {
namespace {

// glTF enums (spec/gltf.md).
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;

std::string count_text(const char* what, Eigen::Index got, Eigen::Index want) {
  std::string s = "glb: ";
  s += what;
  s += " has ";
  s += std::to_string(got);
  s += ", expected ";
  s += std::to_string(want);
  return s;
}

void require_finite(const float* data, Eigen::Index size, const char* what) {
  for (Eigen::Index i = 0; i < size; ++i)
    if (!std::isfinite(data[i])) throw std::invalid_argument(std::string("glb: ") + what + " holds a non-finite value");
}

// Appends raw bytes as a new buffer view (4-byte aligned, as accessors of floats and uint32
// need) and returns its index.
int add_view(tinygltf::Model& model, const void* data, std::size_t bytes, int target) {
  auto& buffer = model.buffers[0].data;
  buffer.resize((buffer.size() + 3) / 4 * 4, 0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = buffer.size();
  view.byteLength = bytes;
  view.target = target;
  const auto* p = static_cast<const unsigned char*>(data);
  buffer.insert(buffer.end(), p, p + bytes);
  model.bufferViews.push_back(view);
  return static_cast<int>(model.bufferViews.size() - 1);
}

// A float accessor of `count` elements of `components` each, with per-component min and max.
int add_float_accessor(tinygltf::Model& model, const float* data, std::size_t count,
                       int components, int target) {
  tinygltf::Accessor accessor;
  accessor.bufferView = add_view(model, data, count * components * sizeof(float), target);
  accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  accessor.count = count;
  accessor.type = components == 3 ? TINYGLTF_TYPE_VEC3 : TINYGLTF_TYPE_SCALAR;
  accessor.minValues.assign(components, std::numeric_limits<double>::infinity());
  accessor.maxValues.assign(components, -std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < count; ++i)
    for (int c = 0; c < components; ++c) {
      const double v = data[i * components + c];
      accessor.minValues[c] = std::min(accessor.minValues[c], v);
      accessor.maxValues[c] = std::max(accessor.maxValues[c], v);
    }
  if (count == 0) {
    accessor.minValues.clear();
    accessor.maxValues.clear();
  }
  model.accessors.push_back(accessor);
  return static_cast<int>(model.accessors.size() - 1);
}

void validate(const MorphAnimation& a) {
  const Eigen::Index n = a.base_positions_m.cols();
  if (n == 0) throw std::invalid_argument("glb: the mesh has no vertices");
  require_finite(a.base_positions_m.data(), a.base_positions_m.size(), "base positions");
  if (a.triangles.cols() == 0) throw std::invalid_argument("glb: the mesh has no triangles");
  for (Eigen::Index i = 0; i < a.triangles.size(); ++i)
    if (a.triangles.data()[i] < 0 || a.triangles.data()[i] >= n)
      throw std::invalid_argument("glb: triangle index " + std::to_string(a.triangles.data()[i]) +
                                  " outside 0.." + std::to_string(n - 1));
  if (a.normals) {
    if (a.normals->cols() != n) throw std::invalid_argument(count_text("normals", a.normals->cols(), n));
    require_finite(a.normals->data(), a.normals->size(), "normals");
  }
  for (const auto& t : a.targets_m) {
    if (t.cols() != n) throw std::invalid_argument(count_text("a morph target", t.cols(), n));
    require_finite(t.data(), t.size(), "a morph target");
  }
  const auto k = static_cast<Eigen::Index>(a.targets_m.size());
  if (!a.target_names.empty() && static_cast<Eigen::Index>(a.target_names.size()) != k)
    throw std::invalid_argument(count_text("target_names", static_cast<Eigen::Index>(a.target_names.size()), k));
  if (a.weights.rows() > 0 && a.weights.cols() != k)
    throw std::invalid_argument(count_text("weights (columns)", a.weights.cols(), k));
  require_finite(a.weights.data(), a.weights.size(), "weights");
  if (!a.rate.valid()) throw std::invalid_argument("glb: invalid frame rate");
}

}  // namespace

Eigen::Matrix3Xf frame_positions(const MorphAnimation& animation, Eigen::Index frame) {
  Eigen::Matrix3Xf out = animation.base_positions_m;
  for (std::size_t k = 0; k < animation.targets_m.size(); ++k) {
    const float w = animation.weights(frame, static_cast<Eigen::Index>(k));
    if (w != 0.0f) out += w * animation.targets_m[k];
  }
  return out;
}

std::string write_glb(const MorphAnimation& a) {
  validate(a);
  const auto n = static_cast<std::size_t>(a.base_positions_m.cols());
  const auto k = a.targets_m.size();
  const auto frames = static_cast<std::size_t>(a.weights.rows());

  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "fapcast";
  model.buffers.resize(1);

  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.attributes["POSITION"] =
      add_float_accessor(model, a.base_positions_m.data(), n, 3, kArrayBuffer);
  if (a.normals)
    primitive.attributes["NORMAL"] = add_float_accessor(model, a.normals->data(), n, 3, kArrayBuffer);
  {
    std::vector<std::uint32_t> indices(a.triangles.data(), a.triangles.data() + a.triangles.size());
    tinygltf::Accessor accessor;
    accessor.bufferView = add_view(model, indices.data(), indices.size() * 4, kElementArrayBuffer);
    accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    accessor.count = indices.size();
    accessor.type = TINYGLTF_TYPE_SCALAR;
    model.accessors.push_back(accessor);
    primitive.indices = static_cast<int>(model.accessors.size() - 1);
  }
  for (const auto& target : a.targets_m)
    primitive.targets.push_back(
        {{"POSITION", add_float_accessor(model, target.data(), n, 3, kArrayBuffer)}});

  tinygltf::Mesh mesh;
  mesh.name = a.name;
  mesh.primitives.push_back(primitive);
  mesh.weights.assign(k, 0.0);
  if (!a.target_names.empty()) {
    // three.js and Blender read morph target names from mesh.extras.targetNames.
    tinygltf::Value::Array names;
    for (const auto& s : a.target_names) names.emplace_back(s);
    tinygltf::Value::Object extras;
    extras["targetNames"] = tinygltf::Value(names);
    mesh.extras = tinygltf::Value(extras);
  }
  model.meshes.push_back(mesh);

  tinygltf::Node node;
  node.name = a.name;
  node.mesh = 0;
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes.push_back(0);
  model.scenes.push_back(scene);
  model.defaultScene = 0;

  if (frames > 0 && k > 0) {
    std::vector<float> times(frames);
    for (std::size_t f = 0; f < frames; ++f)
      times[f] = static_cast<float>(static_cast<double>(f) * a.rate.denominator / a.rate.numerator);
    // glTF wants the weights frame-major (all K of frame 0, then frame 1 ...): row-major F x K.
    const Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rows = a.weights;
    tinygltf::AnimationSampler sampler;
    sampler.input = add_float_accessor(model, times.data(), frames, 1, 0);
    sampler.output = add_float_accessor(model, rows.data(), frames * k, 1, 0);
    sampler.interpolation = "LINEAR";
    tinygltf::AnimationChannel channel;
    channel.sampler = 0;
    channel.target_node = 0;
    channel.target_path = "weights";
    tinygltf::Animation animation;
    animation.name = a.name;
    animation.samplers.push_back(sampler);
    animation.channels.push_back(channel);
    model.animations.push_back(animation);
  }
  // Animation sampler views must not carry a target (spec/gltf.md); tinygltf omits target 0.
  std::ostringstream out;
  tinygltf::TinyGLTF gltf;
  if (!gltf.WriteGltfSceneToStream(&model, out, false, true))
    throw std::runtime_error("glb: tinygltf could not serialise the model");
  return std::move(out).str();
}

namespace {

[[noreturn]] void fail(const std::string& source, const std::string& rule, const std::string& detail) {
  throw InputError({source, std::nullopt, std::nullopt}, rule, detail);
}

[[noreturn]] void fail_at(const std::string& source, std::uint64_t offset, const std::string& detail) {
  throw InputError({source, std::nullopt, offset}, "glb-container", detail);
}

std::uint32_t le32(std::string_view bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(i)]);
  return v;
}

// The GLB container, checked before tinygltf sees it: tinygltf 2.7 lets a BIN chunk run up to
// 8 bytes past the declared length, so the lengths are held to the byte here.
void check_container(std::string_view b, const std::string& source) {
  if (b.size() < 20) fail_at(source, 0, "shorter than the 20-byte GLB header and chunk header");
  if (b.substr(0, 4) != "glTF") fail_at(source, 0, "no 'glTF' magic");
  if (le32(b, 4) != 2) fail_at(source, 4, "GLB version " + std::to_string(le32(b, 4)) + ", 2 expected");
  if (le32(b, 8) != b.size())
    fail_at(source, 8, "header length " + std::to_string(le32(b, 8)) + " but the file has " +
                           std::to_string(b.size()) + " bytes");
  const std::uint64_t json = le32(b, 12);
  if (json == 0 || json % 4 != 0 || 20 + json > b.size())
    fail_at(source, 12, "JSON chunk length " + std::to_string(json) + " is 0, unaligned or past the end");
  if (le32(b, 16) != 0x4E4F534Au) fail_at(source, 16, "first chunk is not JSON");
  const std::uint64_t bin = 20 + json;
  if (bin == b.size()) return;
  if (bin + 8 > b.size()) fail_at(source, bin, "truncated BIN chunk header");
  const std::uint64_t bin_length = le32(b, bin);
  if (bin_length % 4 != 0 || bin + 8 + bin_length != b.size())
    fail_at(source, bin, "BIN chunk length " + std::to_string(bin_length) + " does not end the file");
  if (le32(b, bin + 4) != 0x004E4942u) fail_at(source, bin + 4, "second chunk is not BIN");
}

// The floats of a FLOAT accessor of `components` per element, bounds-checked.
std::vector<float> read_floats(const tinygltf::Model& m, int index, int components,
                               const std::string& source, const char* what) {
  if (index < 0 || static_cast<std::size_t>(index) >= m.accessors.size())
    fail(source, "gltf-accessor", std::string(what) + ": no accessor " + std::to_string(index));
  const auto& acc = m.accessors[static_cast<std::size_t>(index)];
  const int want_type = components == 3 ? TINYGLTF_TYPE_VEC3 : TINYGLTF_TYPE_SCALAR;
  if (acc.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || acc.type != want_type || acc.sparse.isSparse)
    fail(source, "gltf-accessor-type", std::string(what) + ": needs a dense float accessor");
  if (acc.bufferView < 0 || static_cast<std::size_t>(acc.bufferView) >= m.bufferViews.size())
    fail(source, "gltf-accessor", std::string(what) + ": no buffer view");
  const auto& view = m.bufferViews[static_cast<std::size_t>(acc.bufferView)];
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= m.buffers.size())
    fail(source, "gltf-accessor", std::string(what) + ": no buffer");
  const auto& buffer = m.buffers[static_cast<std::size_t>(view.buffer)].data;
  const std::size_t element = static_cast<std::size_t>(components) * sizeof(float);
  const std::size_t stride = view.byteStride == 0 ? element : view.byteStride;
  const std::size_t start = view.byteOffset + acc.byteOffset;
  if (stride < element || acc.count > (buffer.size() / stride) + 1 ||
      (acc.count > 0 && start + (acc.count - 1) * stride + element > buffer.size()) ||
      (acc.count > 0 && acc.byteOffset + (acc.count - 1) * stride + element > view.byteLength))
    fail(source, "gltf-accessor-bounds", std::string(what) + ": accessor runs past its buffer");
  std::vector<float> out(acc.count * static_cast<std::size_t>(components));
  for (std::size_t i = 0; i < acc.count; ++i)
    std::memcpy(out.data() + i * components, buffer.data() + start + i * stride, element);
  for (const float v : out)
    if (!std::isfinite(v)) fail(source, "gltf-non-finite", std::string(what) + ": non-finite value");
  return out;
}

Eigen::Matrix3Xf to_matrix(const std::vector<float>& xyz) {
  return Eigen::Map<const Eigen::Matrix3Xf>(xyz.data(), 3, static_cast<Eigen::Index>(xyz.size() / 3));
}

// The frame rate whose key times these are: an integer rate, or NTSC's n * 1000 / 1001, from 1
// to kMaxGlbFps. Each key time must lie within float precision of its frame's exact time, and
// that tolerance must stay below a quarter of the frame period (so no neighbouring rate fits too).
constexpr double kMaxGlbFps = 1000;

FrameRate rate_of(const std::vector<float>& times, const std::string& source) {
  if (times.size() < 2) return FrameRate{60, 1};
  const double step = (static_cast<double>(times.back()) - times.front()) / static_cast<double>(times.size() - 1);
  if (!(step > 0)) fail(source, "gltf-key-times", "key times do not increase");
  const double fps = 1.0 / step;
  if (fps > kMaxGlbFps * 1.001 || fps < 0.999)
    fail(source, "gltf-frame-rate", "key times imply " + std::to_string(fps) +
                                        " frames per second, outside 1.." + std::to_string(static_cast<int>(kMaxGlbFps)));
  FrameRate rate{static_cast<std::uint32_t>(std::lround(fps)), 1};
  if (std::abs(fps - rate.numerator) > 1e-4 * fps)
    rate = FrameRate{static_cast<std::uint32_t>(std::lround(fps * 1001)), 1001};
  if (rate.numerator < 1 || rate.fps() > kMaxGlbFps || rate.fps() < 1)
    fail(source, "gltf-frame-rate", "key times imply " + std::to_string(fps) + " frames per second");
  const double period = 1.0 / rate.fps();
  constexpr double kFloatEpsilon = 1.0 / (1 << 23);
  for (std::size_t f = 0; f < times.size(); ++f) {
    const double want = static_cast<double>(f) * rate.denominator / rate.numerator;
    const double tolerance = 4 * kFloatEpsilon * std::max(1.0, want);
    if (tolerance >= period / 4)
      fail(source, "gltf-key-times", "key time " + std::to_string(f) + " (" + std::to_string(want) +
                                         " s) is too late for float key times at this rate");
    if (std::abs(times[f] - want) > tolerance)
      fail(source, "gltf-key-times", "key time " + std::to_string(f) + " is " +
                                         std::to_string(times[f]) + " s, not on a constant rate");
  }
  return rate;
}

}  // namespace

MorphAnimation read_glb(std::string_view bytes, const std::string& source) {
  tinygltf::Model m;
  tinygltf::TinyGLTF gltf;
  std::string err, warn;
  if (bytes.size() > std::numeric_limits<unsigned int>::max())
    fail(source, "glb-too-large", "more than 4 GiB");
  check_container(bytes, source);
  if (!gltf.LoadBinaryFromMemory(&m, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                 static_cast<unsigned int>(bytes.size())))
    fail(source, "glb-syntax", err.empty() ? "tinygltf refused the file" : err);
  if (m.meshes.size() != 1 || m.meshes[0].primitives.size() != 1)
    fail(source, "gltf-one-mesh", "needs exactly one mesh with one primitive");
  const auto& p = m.meshes[0].primitives[0];
  if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != -1)
    fail(source, "gltf-triangles", "the primitive is not a triangle list");
  MorphAnimation a;
  a.name = m.meshes[0].name;
  const auto pos = p.attributes.find("POSITION");
  if (pos == p.attributes.end()) fail(source, "gltf-position", "the primitive has no POSITION");
  a.base_positions_m = to_matrix(read_floats(m, pos->second, 3, source, "POSITION"));
  const Eigen::Index n = a.base_positions_m.cols();
  if (const auto nor = p.attributes.find("NORMAL"); nor != p.attributes.end()) {
    a.normals = to_matrix(read_floats(m, nor->second, 3, source, "NORMAL"));
    if (a.normals->cols() != n) fail(source, "gltf-count", "NORMAL and POSITION counts differ");
  }
  // Indices: uint32 as write_glb writes them, also uint16 / uint8 from other writers.
  if (p.indices < 0 || static_cast<std::size_t>(p.indices) >= m.accessors.size())
    fail(source, "gltf-indices", "the primitive has no index accessor");
  {
    const auto& acc = m.accessors[static_cast<std::size_t>(p.indices)];
    const int size = acc.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT    ? 4
                     : acc.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                     : acc.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE  ? 1
                                                                                    : 0;
    if (size == 0 || acc.type != TINYGLTF_TYPE_SCALAR || acc.count % 3 != 0 || acc.sparse.isSparse ||
        acc.bufferView < 0 || static_cast<std::size_t>(acc.bufferView) >= m.bufferViews.size())
      fail(source, "gltf-indices", "indices must be a scalar unsigned accessor, 3 per triangle");
    const auto& view = m.bufferViews[static_cast<std::size_t>(acc.bufferView)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= m.buffers.size())
      fail(source, "gltf-indices", "no buffer");
    const auto& buffer = m.buffers[static_cast<std::size_t>(view.buffer)].data;
    const std::size_t start = view.byteOffset + acc.byteOffset;
    if (acc.count > buffer.size() || start + acc.count * size > buffer.size() ||
        acc.byteOffset + acc.count * size > view.byteLength)
      fail(source, "gltf-accessor-bounds", "indices run past their buffer");
    a.triangles.resize(3, static_cast<Eigen::Index>(acc.count / 3));
    for (std::size_t i = 0; i < acc.count; ++i) {
      std::uint32_t v = 0;
      std::memcpy(&v, buffer.data() + start + i * size, static_cast<std::size_t>(size));  // little-endian
      if (v >= static_cast<std::uint32_t>(n))
        fail(source, "gltf-index-range", "index " + std::to_string(v) + " with " + std::to_string(n) + " vertices");
      a.triangles.data()[i] = static_cast<int>(v);
    }
  }
  for (const auto& target : p.targets) {
    const auto t = target.find("POSITION");
    if (t == target.end()) fail(source, "gltf-target", "a morph target has no POSITION");
    a.targets_m.push_back(to_matrix(read_floats(m, t->second, 3, source, "target POSITION")));
    if (a.targets_m.back().cols() != n) fail(source, "gltf-count", "a morph target's count differs from POSITION");
  }
  const auto& extras = m.meshes[0].extras;
  if (extras.IsObject() && extras.Has("targetNames") && extras.Get("targetNames").IsArray()) {
    const auto& names = extras.Get("targetNames");
    for (std::size_t i = 0; i < names.ArrayLen(); ++i)
      a.target_names.push_back(names.Get(static_cast<int>(i)).IsString() ? names.Get(static_cast<int>(i)).Get<std::string>() : "");
    if (a.target_names.size() != a.targets_m.size()) a.target_names.clear();
  }
  const auto k = static_cast<Eigen::Index>(a.targets_m.size());
  a.weights.resize(0, k);
  if (m.animations.size() > 1) fail(source, "gltf-one-animation", "more than one animation");
  if (!m.animations.empty()) {
    const auto& anim = m.animations[0];
    if (anim.channels.size() != 1 || anim.channels[0].target_path != "weights" ||
        anim.channels[0].sampler < 0 || static_cast<std::size_t>(anim.channels[0].sampler) >= anim.samplers.size())
      fail(source, "gltf-weights-animation", "the animation must have one weights channel");
    const auto& sampler = anim.samplers[static_cast<std::size_t>(anim.channels[0].sampler)];
    if (sampler.interpolation != "LINEAR" && !sampler.interpolation.empty())
      fail(source, "gltf-weights-animation", "interpolation " + sampler.interpolation + " (LINEAR expected)");
    const auto times = read_floats(m, sampler.input, 1, source, "sampler input");
    const auto values = read_floats(m, sampler.output, 1, source, "sampler output");
    if (k == 0 || values.size() != times.size() * static_cast<std::size_t>(k))
      fail(source, "gltf-count", "sampler output holds " + std::to_string(values.size()) +
                                     " weights for " + std::to_string(times.size()) + " keys");
    a.rate = rate_of(times, source);
    const auto frames = static_cast<Eigen::Index>(times.size());
    a.weights = Eigen::Map<const Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
        values.data(), frames, k);
  }
  return a;
}

}  // namespace fapcast
