#include "fapcast/synth/data_root.hpp"

#include <cstdlib>

namespace fapcast::synth {

std::filesystem::path data_root() {
  if (const char* env = std::getenv("FAPCAST_DATA"); env != nullptr && *env != '\0') return env;
  return FAPCAST_DATA_DIR;
}

}  // namespace fapcast::synth
