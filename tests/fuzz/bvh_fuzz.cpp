// libFuzzer target for the BVH reader: any bytes either fail with InputError or give a document
// that writes and reads back to itself.
#include "fapcast/codec/bvh_text.hpp"
#include "fapcast/core/input_error.hpp"

#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapcast;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  BvhDocument doc;
  try {
    doc = read_bvh(bytes, "fuzz.bvh");
  } catch (const InputError&) {
    return 0;
  }
  if (doc.motion.size() != doc.frame_count * doc.channel_count()) std::abort();
  if (read_bvh(write_bvh(doc), "rewritten.bvh") != doc) std::abort();
  return 0;
}
