#include "fapcast/codec/fap_frame.hpp"

namespace fapcast {

std::ostream& operator<<(std::ostream& out, const FapMask& mask) {
  out << '{';
  bool first = true;
  for (int n = 1; n <= kFapCount; ++n) {
    if (!mask.test(n)) continue;
    out << (first ? "" : ", ") << n << ' ' << fap_info(n).name;
    first = false;
  }
  return out << '}';
}

std::ostream& operator<<(std::ostream& out, const FapFrame& f) {
  out << '{';
  const char* sep = "";
  if (f.mask.test(kVisemeFap)) {
    const auto& v = f.viseme;
    out << "viseme=(" << int{v.select1} << ',' << int{v.select2} << ',' << int{v.blend} << ','
        << v.def << ')';
    sep = " ";
  }
  if (f.mask.test(kExpressionFap)) {
    const auto& e = f.expression;
    out << sep << "expression=(" << int{e.select1} << ',' << int{e.intensity1} << ','
        << int{e.select2} << ',' << int{e.intensity2} << ',' << e.init_face << ',' << e.def << ')';
    sep = " ";
  }
  for (int n = kFirstLowLevelFap; n <= kFapCount; ++n) {
    if (!f.mask.test(n)) continue;
    out << sep << fap_info(n).name << '=' << f.value(n);
    sep = " ";
  }
  return out << '}';
}

std::ostream& operator<<(std::ostream& out, const FapSequence& seq) {
  out << "FapSequence{\"" << seq.name << "\", " << seq.rate << ", " << seq.frames.size()
      << " frames";
  constexpr std::size_t kPrintAtMost = 8;
  for (std::size_t i = 0; i < seq.frames.size() && i < kPrintAtMost; ++i)
    out << "\n  " << i << ": " << seq.frames[i];
  if (seq.frames.size() > kPrintAtMost) out << "\n  ...";
  return out << '}';
}

}  // namespace fapcast
