// The default voice is a function of its cache key (spec/voice.md "The default voice"): whatever
// the command that first needed it spoke before, the voice built is the same bytes.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli/fapcast_command.hpp"
#include "fapcast/core/file_io.hpp"
#include "support/run_command.hpp"

namespace fapcast {
namespace {

namespace fs = std::filesystem;

// The cached voice file of `dir`'s only entry.
std::string cached_voice(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir)) files.push_back(e.path());
  EXPECT_EQ(files.size(), 1u) << dir;
  return files.empty() ? std::string() : read_file(files.front().string());
}

// espeak-ng carries synthesiser state from call to call, so a corpus recorded in the process that
// had just spoken the user's text would depend on that text: two `say` commands of different texts
// into empty caches build one voice, byte for byte (SOURCE_DATE_EPOCH fixes the build time).
TEST(DefaultVoice, IsTheSameBytesWhicheverTextFirstNeededIt) {
  const fs::path root = test::make_temp_dir("default-voice");
  const auto say_into = [&](const std::string& name, const std::string& text) {
    const fs::path cache = root / name;
    const auto r = test::run_command("SOURCE_DATE_EPOCH=1700000000 FAPCAST_CACHE_DIR='" + cache.string() + "' " +
                                     test::fapcast("say -q \"" + text + "\" -o " + (root / (name + ".fap")).string()));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    // The child that records the corpus says nothing on standard output: it may be the track.
    EXPECT_EQ(r.out.find("SYNTHETIC reference corpus in"), std::string::npos) << r.out;
    return cached_voice(cache);
  };
  const std::string a = say_into("a", "Hello there.");
  const std::string b = say_into("b", "A different sentence, about lips and jaws, read first.");
  ASSERT_FALSE(a.empty());
  EXPECT_TRUE(a == b) << "the two default voices differ (" << a.size() << " and " << b.size() << " bytes)";
}

}  // namespace
}  // namespace fapcast
