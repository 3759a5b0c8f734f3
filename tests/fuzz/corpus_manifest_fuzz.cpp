// libFuzzer: any bytes as a corpus's manifest.json through list_corpus, in a folder that holds
// a few marker files and alignments for it to name. Either InputError, or a listing of at least
// one utterance whose marker file and alignment exist and are of the extensions the build reads.
#include "fapcast/builder/voice_corpus.hpp"
#include "fapcast/core/input_error.hpp"
#include "fuzz/support/scratch_file.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace {

bool one_of(const std::filesystem::path& file, std::span<const std::string_view> extensions) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return std::find(extensions.begin(), extensions.end(), ext) != extensions.end();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapcast;
  static const bool made = [] {
    for (const char* name : {"u1.csv", "u1.lab", "u2.c3d", "u2.TextGrid", "u3.trc", "u3.lab", "u4.bvh"})
      fuzz::scratch_file(std::string("corpus/") + name, "");
    return true;
  }();
  (void)made;
  fuzz::scratch_file("corpus/manifest.json", {reinterpret_cast<const char*>(data), size});
  CorpusListing listing;
  try {
    listing = list_corpus(fuzz::scratch_dir() / "corpus");
  } catch (const InputError&) {
    return 0;
  }
  if (listing.utterances.empty()) std::abort();
  for (const CorpusUtterance& u : listing.utterances) {
    if (!std::filesystem::exists(u.markers) || !std::filesystem::exists(u.alignment)) std::abort();
    if (!one_of(u.markers, kMarkerExtensions) || !one_of(u.alignment, kAlignmentExtensions)) std::abort();
  }
  return 0;
}
