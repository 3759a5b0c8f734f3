#pragma once
// Large buffers written once from start to end (a chunk's speech, a text's frames): asking the
// kernel for transparent huge pages on them makes the first write fault once per 2 MiB instead of
// once per 4 KiB page. Page faults are the dearest thing `say` does after espeak-ng on a virtual
// machine (spec/phones.md, "The whole command").
#include <cstddef>
#include <vector>

namespace fapcast {

// Advises the kernel (madvise MADV_HUGEPAGE) that [data, data + bytes) is best backed by huge
// pages. Only whole 2 MiB-aligned huge pages inside the mapping benefit; a buffer below 2 MiB, a
// kernel without transparent huge pages or a refusal changes nothing (the advice is a hint: the
// bytes are the same either way).
void advise_huge_pages(const void* data, std::size_t bytes);

// The same for the capacity of a vector, before its elements are written.
template <class T>
void advise_huge_pages(const std::vector<T>& buffer) {
  advise_huge_pages(buffer.data(), buffer.capacity() * sizeof(T));
}

}  // namespace fapcast
