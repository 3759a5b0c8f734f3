#include "output_check.hpp"

#include "fapcast/core/file_io.hpp"

namespace fapcast::cli {

void check_output_writable(const std::filesystem::path& path) {
  if (path.empty()) return;
  const AtomicFile probe(path);  // its destructor removes the temporary file it created
}

}  // namespace fapcast::cli
