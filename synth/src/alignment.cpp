#include "fapcast/synth/alignment.hpp"

namespace fapcast::synth {

const LabelTier* Alignment::find(std::string_view name) const {
  for (const LabelTier& tier : tiers) {
    if (tier.name == name) return &tier;
  }
  return nullptr;
}

std::ostream& operator<<(std::ostream& out, const Alignment& alignment) {
  out << "Alignment [" << alignment.start_s << ", " << alignment.end_s << "]";
  for (const LabelTier& tier : alignment.tiers) out << "\n" << tier;
  return out;
}

}  // namespace fapcast::synth
