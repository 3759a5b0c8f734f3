#pragma once
// Whole-file reads with a size limit, and atomic writes (temporary file + rename), so that a
// crash or a full disk never leaves a half-written output where a good one was, and a killed
// run's temporary files are swept by the next write to the same directory.
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>

namespace fapcast {

// Default ceiling for read_file: far above any real .fap/.fba/.wav we read whole, far below
// what would hurt the machine.
inline constexpr std::uint64_t kDefaultMaxFileBytes = 1ull << 30;  // 1 GiB

// Reads a regular file whole. Throws std::runtime_error naming the file when it cannot be
// opened, is not a regular file, or is larger than `max_bytes` (checked before reading).
std::string read_file(const std::filesystem::path& path,
                      std::uint64_t max_bytes = kDefaultMaxFileBytes);

// An output being written: the temporary file `.NAME.fapcast-tmpNNN` (NNN decimal digits) beside `path`
// is created and locked (flock) at construction, so a command learns that it cannot write its
// output before it does its work; commit() writes it out, fsyncs and renames it over `path`.
// A file never committed is removed by the destructor, on every failure path that unwinds.
// The first file created in a directory sweeps that directory's stale temporary files: names
// of exactly that pattern, regular files, older than this process and locked by no one (a
// killed run's; a running fapcast holds the lock on its own).
class AtomicFile {
 public:
  // Throws std::runtime_error naming `path` when the temporary file cannot be created.
  explicit AtomicFile(std::filesystem::path path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Appends bytes to the temporary file. Throws std::runtime_error naming `path`.
  void write(std::string_view bytes);
  // Appends everything written to `source` so far, copied by the kernel (copy_file_range: no
  // buffer in this process to fill and fault in). Throws std::runtime_error naming `path`.
  void append_contents_of(const AtomicFile& source);
  // Writes bytes at `offset` of the temporary file (pwrite; a header patched after its data,
  // as WavWriter does). Throws std::runtime_error naming `path`.
  void write_at(std::uint64_t offset, std::string_view bytes);
  // fsync, close, rename over path(). Throws std::runtime_error naming `path` and the step.
  void commit();
  const std::filesystem::path& path() const { return path_; }
  const std::filesystem::path& temporary() const { return tmp_; }

 private:
  [[noreturn]] void abandon(const std::string& step, int err);
  std::filesystem::path path_;
  std::filesystem::path tmp_;
  int fd_ = -1;
  bool committed_ = false;
};

// Commits `files` in order, after all of them were written: outputs that belong together (a
// .glb and its WAV) appear together. When one rename fails, the ones renamed before it are
// removed again, so neither appears (a file they replaced is gone then: it was being replaced).
void commit_together(std::initializer_list<AtomicFile*> files);

// Writes `bytes` to `path` atomically (AtomicFile). On failure the temporary file is removed,
// `path` is untouched, and std::runtime_error names the file and the failing step.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

// Whether the sweep would remove `file`: a stale temporary file of a killed run.
bool is_stale_temporary(const std::filesystem::path& file);

}  // namespace fapcast
