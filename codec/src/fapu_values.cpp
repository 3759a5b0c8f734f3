#include "fapcast/codec/fapu_values.hpp"

#include <stdexcept>
#include <string>

namespace fapcast {

double FapuValues::of(Fapu unit) const {
  switch (unit) {
    case Fapu::kMNS: return mns;
    case Fapu::kMW: return mw;
    case Fapu::kENS: return ens;
    case Fapu::kES: return es;
    case Fapu::kIRISD: return irisd;
    case Fapu::kAU: return kAngleUnitRad;
    case Fapu::kNone: return 0.0;
  }
  return 0.0;
}

std::ostream& operator<<(std::ostream& out, const FapuValues& f) {
  return out << "FAPU{MNS=" << f.mns << " MW=" << f.mw << " ENS=" << f.ens << " ES=" << f.es
             << " IRISD=" << f.irisd << "}";
}

FapuValues measure_fapu(const FeaturePointPositions& neutral) {
  auto at = [&](FeaturePoint fp) -> const Eigen::Vector3d& {
    const auto it = neutral.find(fp);
    if (it == neutral.end())
      throw std::invalid_argument("FAPU: neutral feature point " + fp.label() + " is missing");
    return it->second;
  };
  auto unit = [](const char* name, double distance) {
    if (!(distance > 0.0))
      throw std::invalid_argument(std::string("FAPU: ") + name + " distance is " +
                                  std::to_string(distance) + ", must be positive");
    return distance / 1024.0;
  };
  FapuValues f{};
  f.mns = unit("MNS (9.15.y - 2.2.y)", at({9, 15}).y() - at({2, 2}).y());
  f.mw = unit("MW (8.3.x - 8.4.x)", at({8, 3}).x() - at({8, 4}).x());
  f.ens = unit("ENS (3.5.y - 9.15.y)", at({3, 5}).y() - at({9, 15}).y());
  f.es = unit("ES (3.5.x - 3.6.x)", at({3, 5}).x() - at({3, 6}).x());
  f.irisd = unit("IRISD (3.1.y - 3.3.y)", at({3, 1}).y() - at({3, 3}).y());
  return f;
}

}  // namespace fapcast
