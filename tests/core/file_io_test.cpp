// Atomic outputs (issue #17, attack 10): no debris on failure, a killed run's temporary files
// swept by the next write to the same directory (ours only, and only stale ones), outputs that
// belong together committed together.
#include "fapcast/core/file_io.hpp"
#include "fapcast/core/huge_pages.hpp"
#include "fapcast/core/input_error.hpp"
#include "support/run_command.hpp"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>
#include <utime.h>

#include <ctime>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fapcast {
namespace {
namespace fs = std::filesystem;

void touch(const fs::path& p, std::time_t mtime) {
  std::ofstream(p) << "x";
  const utimbuf times{mtime, mtime};
  ASSERT_EQ(::utime(p.c_str(), &times), 0);
}

std::size_t files_in(const fs::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(AtomicFile, AnUncommittedFileLeavesNothingBehind) {
  const fs::path dir = test::make_temp_dir("atomic");
  std::ofstream(dir / "o.fap") << "old";
  {
    AtomicFile f(dir / "o.fap");
    EXPECT_TRUE(fs::exists(f.temporary()));
    f.write("new, never committed");
  }
  EXPECT_EQ(files_in(dir), 1u);  // the temporary file is gone, the old output untouched
  EXPECT_EQ(read_file(dir / "o.fap"), "old");
}

TEST(AtomicFile, AppendsAnotherFilesContentsBetweenItsOwnWrites) {
  const fs::path dir = test::make_temp_dir("atomic-append");
  AtomicFile body(dir / "body");
  std::string lines;
  for (int i = 0; i < 20000; ++i) lines += "line " + std::to_string(i) + "\n";  // several copy calls' worth
  body.write(lines);
  AtomicFile out(dir / "o.fap");
  out.write("header\n");
  out.append_contents_of(body);
  out.write("tail\n");
  out.append_contents_of(body);  // from its start again, whatever was read before
  out.commit();
  EXPECT_EQ(read_file(dir / "o.fap"), "header\n" + lines + "tail\n" + lines);
  AtomicFile empty(dir / "empty");
  AtomicFile after(dir / "after");
  after.append_contents_of(empty);
  after.commit();
  EXPECT_EQ(read_file(dir / "after"), "");
}

TEST(AtomicFile, AnOutputThatCannotBeCreatedFailsAtOnce) {
  try {
    AtomicFile f("/nonexistent/dir/o.fap");
    FAIL() << "created " << f.temporary();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/o.fap"), std::string::npos) << e.what();
  }
}

// A killed run's `.NAME.fapcast-tmpNNN`, older than this process and locked by no one, is swept by the
// next write to its directory; names not of that pattern, newer files and locked ones stay.
TEST(AtomicFile, TheNextWriteSweepsAKilledRunsTemporaryFiles) {
  const fs::path dir = test::make_temp_dir("sweep");
  const std::time_t hour_ago = std::time(nullptr) - 3600;
  touch(dir / ".o.fap.fapcast-tmp123", hour_ago);      // stale: swept
  touch(dir / ".other.json.fapcast-tmp9", hour_ago);   // stale, another output's: swept too
  touch(dir / ".o.fap.fapcast-tmpx", hour_ago);        // not our pattern
  touch(dir / "o.fap.fapcast-tmp7", hour_ago);         // not hidden: not ours
  touch(dir / ".notes.fapcast-tmp", hour_ago);         // no digits
  touch(dir / ".config.json.tmp12345", hour_ago);      // another program's temporary file
  touch(dir / ".fresh.fap.fapcast-tmp5", std::time(nullptr) + 60);  // not older than this run
  touch(dir / ".locked.fap.fapcast-tmp6", hour_ago);   // a running fapcast holds its lock
  const int held = ::open((dir / ".locked.fap.fapcast-tmp6").c_str(), O_RDONLY);
  ASSERT_GE(held, 0);
  ASSERT_EQ(::flock(held, LOCK_EX | LOCK_NB), 0);
  EXPECT_TRUE(is_stale_temporary(dir / ".o.fap.fapcast-tmp123"));
  EXPECT_FALSE(is_stale_temporary(dir / ".locked.fap.fapcast-tmp6"));

  write_file_atomically(dir / "o.fap", "frames");
  ::close(held);
  EXPECT_FALSE(fs::exists(dir / ".o.fap.fapcast-tmp123"));
  EXPECT_FALSE(fs::exists(dir / ".other.json.fapcast-tmp9"));
  for (const char* kept : {".o.fap.fapcast-tmpx", "o.fap.fapcast-tmp7", ".notes.fapcast-tmp", ".config.json.tmp12345", ".fresh.fap.fapcast-tmp5", ".locked.fap.fapcast-tmp6"})
    EXPECT_TRUE(fs::exists(dir / kept)) << kept;
  EXPECT_EQ(read_file(dir / "o.fap"), "frames");
}

// A .glb and its WAV: when the second cannot be renamed, the first is removed again.
TEST(AtomicFile, OutputsCommittedTogetherAllAppearOrNone) {
  const fs::path dir = test::make_temp_dir("together");
  {
    AtomicFile a(dir / "x.glb"), b(dir / "x.wav");
    a.write("glb");
    b.write("wav");
    commit_together({&a, &b});
  }
  EXPECT_EQ(read_file(dir / "x.glb"), "glb");
  EXPECT_EQ(read_file(dir / "x.wav"), "wav");

  {
    AtomicFile a(dir / "y.glb"), b(dir / "y.wav");
    a.write("glb");
    b.write("wav");
    fs::create_directories(dir / "y.wav" / "in-the-way");  // made meanwhile: the rename over it fails
    EXPECT_THROW(commit_together({&a, &b}), std::runtime_error);
  }
  EXPECT_FALSE(fs::exists(dir / "y.glb"));
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find("tmp"), std::string::npos) << e.path();
}

// An output that names a folder is refused when it is opened, before any work is done for it.
TEST(AtomicFile, AFolderIsNoOutput) {
  const fs::path dir = test::make_temp_dir("folder");
  fs::create_directories(dir / "o.fap");
  try {
    AtomicFile f(dir / "o.fap");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("o.fap: is a directory, not a file"), std::string::npos) << e.what();
  }
}

TEST(HugePages, AdviceKeepsTheBytes) {
  std::vector<std::int16_t> samples;
  samples.reserve(std::size_t{3} << 20);  // 6 MiB: holds whole huge pages wherever it lands
  advise_huge_pages(samples);
  for (std::size_t i = 0; i < samples.capacity(); ++i) samples.push_back(static_cast<std::int16_t>(i * 7));
  for (std::size_t i = 0; i < samples.size(); i += 4099) EXPECT_EQ(samples[i], static_cast<std::int16_t>(i * 7));
  advise_huge_pages(nullptr, 0);           // nothing to advise
  advise_huge_pages(samples.data(), 100);  // below a huge page: nothing
}

TEST(ReadFile, RefusesAFileOverItsLimitBeforeReading) {
  const fs::path dir = test::make_temp_dir("limit");
  std::ofstream(dir / "big") << std::string(100, 'x');
  EXPECT_EQ(read_file(dir / "big", 100).size(), 100u);
  EXPECT_THROW(read_file(dir / "big", 99), std::runtime_error);
  EXPECT_THROW(read_file(dir), std::runtime_error);  // not a regular file
}

// Attack 12: raw garbage bytes were echoed into messages.
TEST(EscapeForMessage, WritesControlAndStrayBytesAsHex) {
  EXPECT_EQ(escape_for_message("ab\x01" "c\xff\x1b[2J"), "ab\\x01c\\xff\\x1b[2J");
  EXPECT_EQ(escape_for_message("caf\xc3\xa9 \xe2\x82\xac"), "caf\xc3\xa9 \xe2\x82\xac");  // UTF-8 kept
  EXPECT_EQ(escape_for_message("\xc0\xaf"), "\\xc0\\xaf");           // an overlong '/'
  EXPECT_EQ(escape_for_message("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // a surrogate
  const InputError e({"a.fap", 3, std::nullopt}, "bad-value", "\"\x07\x08\"");
  EXPECT_STREQ(e.what(), "a.fap:3: bad-value: \"\\x07\\x08\"");
}

}  // namespace
}  // namespace fapcast
