#include "fapcast/core/huge_pages.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>

namespace fapcast {

void advise_huge_pages(const void* data, std::size_t bytes) {
  constexpr std::size_t kHugePage = std::size_t{2} << 20;  // x86-64 and arm64 (4 KiB pages)
  if (data == nullptr || bytes < kHugePage) return;
  // madvise wants a page-aligned start: the buffer's whole pages only (the kernel backs with huge
  // pages only the 2 MiB-aligned parts of the range).
  const auto page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
  const auto begin = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t start = (begin + page - 1) & ~(page - 1);
  const std::uintptr_t end = (begin + bytes) & ~(page - 1);
  if (end <= start) return;
#ifdef MADV_HUGEPAGE
  (void)::madvise(reinterpret_cast<void*>(start), end - start, MADV_HUGEPAGE);  // a hint: failure is harmless
#endif
}

}  // namespace fapcast
