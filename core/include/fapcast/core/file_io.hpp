#pragma once
// Whole-file reads with a size limit, and atomic writes (temporary file + rename), so that a
// crash or a full disk never leaves a half-written output where a good one was.
#include <cstdint>
#include <filesystem>
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

// Writes `bytes` to `path` atomically: a temporary file in the same directory, flushed and
// fsync'ed, then renamed over `path`. On failure the temporary file is removed, `path` is
// untouched, and std::runtime_error names the file and the failing step.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace fapcast
