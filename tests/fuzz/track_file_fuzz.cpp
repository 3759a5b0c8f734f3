// libFuzzer: any bytes through the track-file dispatcher (read_track_file: .fap, .fba, .json by
// extension). The first byte picks the extension, in either case or none. Either a refusal
// (InputError, or std::runtime_error naming the file), or a track that writes in its own format
// and reads back with as many frames.
#include "fapcast/core/input_error.hpp"
#include "fapcast/transport/track_file.hpp"
#include "fuzz/support/scratch_file.hpp"

#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapcast;
  if (size == 0) return 0;
  static const char* kNames[] = {"t.fap", "t.fba", "t.json", "t.FAP", "t.Fba", "t.JSON", "t.txt", "t"};
  const std::string name = kNames[data[0] & 7];
  const auto path = fuzz::scratch_file(name, {reinterpret_cast<const char*>(data + 1), size - 1});
  const bool known = track_format_of(path).has_value();
  FapSequence seq;
  try {
    seq = read_track_file(path);
  } catch (const std::runtime_error& e) {
    if (std::string_view(e.what()).find(path.string()) == std::string_view::npos) std::abort();
    return 0;
  }
  if (!known) std::abort();  // an extension the dispatcher does not know was read
  std::string again_bytes;
  try {
    again_bytes = track_file_bytes(path, seq).bytes;
  } catch (const std::runtime_error&) {
    return 0;  // a track read that cannot be coded in its own format again (e.g. values the .fba profile refuses)
  }
  const auto again = fuzz::scratch_file("again-" + name, again_bytes);
  if (read_track_file(again).frames.size() != seq.frames.size()) std::abort();
  return 0;
}
