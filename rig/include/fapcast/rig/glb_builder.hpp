#pragma once
// Building the binary chunk of a glTF 2.0 binary (.glb) next to its JSON: typed accessors appended
// at 4-byte aligned offsets, one buffer view each, and the GLB container (12-byte header, JSON chunk
// padded with spaces, BIN chunk padded with zeros). Used to write new files (VRMA) and to append an
// animation to a user's avatar without touching anything already in it.
#include <nlohmann/json.hpp>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace fapcast {

class GlbBuilder {
 public:
  // Starts from an existing JSON and BIN chunk (an avatar; bin may be empty) or from nothing.
  GlbBuilder(nlohmann::json json, std::vector<std::uint8_t> bin);
  GlbBuilder() : GlbBuilder(nlohmann::json::object(), {}) {}

  nlohmann::json& json() { return json_; }
  // Appends `values` as an accessor of `type` ("SCALAR", "VEC3") floats with min/max; returns its index.
  int add_float_accessor(std::span<const float> values, const char* type, bool with_bounds);
  // The .glb bytes (buffer 0 = the BIN chunk, its byteLength set).
  std::string finish();

 private:
  nlohmann::json json_;
  std::vector<std::uint8_t> bin_;
};

}  // namespace fapcast
