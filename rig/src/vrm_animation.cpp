#include "fapcast/rig/vrm_animation.hpp"

#include <array>
#include <set>
#include <stdexcept>
#include <vector>

#include "fapcast/rig/glb_builder.hpp"

namespace fapcast {

bool is_vrm_preset_expression(std::string_view name) {
  static constexpr std::array<std::string_view, 18> kPresets{
      "happy", "angry", "sad", "relaxed", "surprised", "aa", "ih", "ou", "ee", "oh",
      "blink", "blinkLeft", "blinkRight", "lookUp", "lookDown", "lookLeft", "lookRight", "neutral"};
  for (std::string_view p : kPresets)
    if (p == name) return true;
  return false;
}

std::string write_vrm_animation(std::span<const std::string> names, const Eigen::MatrixXf& weights,
                                FrameRate rate) {
  if (!rate.valid()) throw std::invalid_argument("write_vrm_animation: invalid rate");
  if (weights.rows() < 1 || weights.cols() != static_cast<Eigen::Index>(names.size()) || names.empty())
    throw std::invalid_argument("write_vrm_animation: want frames x names weights, at least one of each");
  std::set<std::string_view> seen;
  for (const std::string& n : names)
    if (n.empty() || !seen.insert(n).second) throw std::invalid_argument("write_vrm_animation: empty or repeated name '" + n + "'");
  GlbBuilder glb;
  auto& j = glb.json();
  j["asset"] = {{"version", "2.0"}, {"generator", "fapcast"}};
  j["extensionsUsed"] = {"VRMC_vrm_animation"};
  j["nodes"] = nlohmann::json::array();
  j["nodes"].push_back({{"name", "hips"}, {"translation", {0.0, 1.0, 0.0}}});
  nlohmann::json scene_nodes = {0};
  nlohmann::json preset = nlohmann::json::object(), custom = nlohmann::json::object();
  for (std::size_t e = 0; e < names.size(); ++e) {
    j["nodes"].push_back({{"name", names[e]}});
    scene_nodes.push_back(e + 1);
    (is_vrm_preset_expression(names[e]) ? preset : custom)[names[e]] = {{"node", e + 1}};
  }
  j["scene"] = 0;
  j["scenes"] = {{{"nodes", scene_nodes}}};
  nlohmann::json expressions = nlohmann::json::object();
  if (!preset.empty()) expressions["preset"] = preset;
  if (!custom.empty()) expressions["custom"] = custom;
  j["extensions"]["VRMC_vrm_animation"] = {{"specVersion", "1.0"},
                                           {"humanoid", {{"humanBones", {{"hips", {{"node", 0}}}}}}},
                                           {"expressions", expressions}};
  const Eigen::Index frames = weights.rows();
  std::vector<float> times(static_cast<std::size_t>(frames));
  for (Eigen::Index f = 0; f < frames; ++f) times[static_cast<std::size_t>(f)] = static_cast<float>(static_cast<double>(f) * rate.denominator / rate.numerator);
  const int input = glb.add_float_accessor(times, "SCALAR", true);
  nlohmann::json samplers = nlohmann::json::array(), channels = nlohmann::json::array();
  std::vector<float> xyz(static_cast<std::size_t>(3 * frames), 0.0f);
  for (std::size_t e = 0; e < names.size(); ++e) {
    for (Eigen::Index f = 0; f < frames; ++f) xyz[static_cast<std::size_t>(3 * f)] = weights(f, static_cast<Eigen::Index>(e));
    const int output = glb.add_float_accessor(xyz, "VEC3", false);
    samplers.push_back({{"input", input}, {"output", output}, {"interpolation", "LINEAR"}});
    channels.push_back({{"sampler", e}, {"target", {{"node", e + 1}, {"path", "translation"}}}});
  }
  j["animations"] = {{{"name", "fapcast"}, {"samplers", samplers}, {"channels", channels}}};
  return glb.finish();
}

}  // namespace fapcast
