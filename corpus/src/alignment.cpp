#include "fapcast/corpus/alignment.hpp"

#include "fapcast/core/synthetic_label.hpp"

namespace fapcast {

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

void mark_synthetic(Alignment& alignment) {
  if (is_synthetic(alignment)) return;
  alignment.tiers.push_back({"provenance", TierKind::points, alignment.start_s, alignment.end_s, {},
                             {{alignment.start_s, std::string(kSyntheticLabel)}}});
}

bool is_synthetic(const Alignment& alignment) {
  for (const LabelTier& tier : alignment.tiers) {
    if (tier.name == "provenance" && tier.kind == TierKind::points && !tier.points.empty() &&
        tier.points.front().mark == kSyntheticLabel) {
      return true;
    }
  }
  return false;
}

}  // namespace fapcast
