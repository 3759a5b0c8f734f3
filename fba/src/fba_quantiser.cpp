#include "fapcast/fba/fba_quantiser.hpp"

#include "fapcast/codec/fap_table.hpp"

namespace fapcast {

int fba_step(int fap, int fap_quant) {
  return fap_quant == 0 ? 1 : fap_info(fap).qp * fap_quant;
}

std::int64_t fba_quantise(std::int64_t value, int step) {
  const std::int64_t magnitude = value < 0 ? -value : value;
  const std::int64_t half = step / 2;
  if (magnitude <= half) return 0;
  const std::int64_t level = (magnitude + half) / step;
  return value < 0 ? -level : level;
}

}  // namespace fapcast
