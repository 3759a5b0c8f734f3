// libFuzzer target for the FAP JSON reader: any bytes either fail with InputError or give a
// sequence that writes and reads back to itself and exports to BVH without trouble.
#include "fapcast/codec/bvh_export.hpp"
#include "fapcast/codec/bvh_text.hpp"
#include "fapcast/core/input_error.hpp"
#include "fapcast/codec/json_export.hpp"

#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapcast;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  FapJsonRead read;
  try {
    read = read_fap_json(bytes, "fuzz.json");
  } catch (const InputError&) {
    return 0;
  }
  const FapJsonRead again = read_fap_json(write_fap_json(read.sequence, read.options), "again.json");
  if (!(again.sequence == read.sequence) || again.options.sample_rate != read.options.sample_rate ||
      again.options.fapu != read.options.fapu)
    std::abort();
  static const FaceGeometry face = generic_adult_face();
  const BvhDocument doc = fap_to_bvh(read.sequence, face);
  if (doc.frame_count != read.sequence.frames.size()) std::abort();
  (void)write_bvh(doc);
  return 0;
}
