#include "lrsvo/graph/large_array.h"

#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace lrsvo {

namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;

}  // namespace

void* allocateLargeArray(std::size_t bytes) {
  if (bytes < kHugePage) return ::operator new(bytes);
  const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
  void* pointer = std::aligned_alloc(kHugePage, rounded);
  if (pointer == nullptr) throw std::bad_alloc();
#if defined(MADV_HUGEPAGE)
  madvise(pointer, rounded, MADV_HUGEPAGE);  // advice: without huge pages the array works the same
#endif
  return pointer;
}

void freeLargeArray(void* pointer, std::size_t bytes) noexcept {
  if (bytes < kHugePage)
    ::operator delete(pointer);
  else
    std::free(pointer);
}

}  // namespace lrsvo
