#include "lrsvo/graph/large_array.h"

#include <cstdint>
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace lrsvo {

namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;

std::size_t roundUp(std::size_t value, std::size_t unit) { return (value + unit - 1) / unit * unit; }

#if defined(__linux__)

std::size_t pageSize() {
  static const std::size_t size = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  return size;
}

// Mapped straight from the kernel rather than through malloc: a freed array
// goes back to the system at once, so it never stays resident unused, and
// the C library's heap never learns to keep arrays of this size.
void* mapAligned(std::size_t bytes) {
  const std::size_t length = roundUp(bytes, pageSize());
  // 2 MiB more than needed, then the ends unmapped: the array starts on a 2 MiB boundary.
  const std::size_t mapped = length + kHugePage;
  void* raw = mmap(nullptr, mapped, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  const auto rawAddress = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t start = roundUp(rawAddress, kHugePage);
  const std::size_t head = start - rawAddress, tail = mapped - head - length;
  if (head > 0) munmap(raw, head);
  if (tail > 0) munmap(reinterpret_cast<void*>(start + length), tail);
  void* pointer = reinterpret_cast<void*>(start);
  // Advice only: without huge pages the array works the same. The partial
  // last 2 MiB ends the mapping, so it keeps small pages.
  madvise(pointer, bytes / kHugePage * kHugePage, MADV_HUGEPAGE);
  return pointer;
}

void unmapAligned(void* pointer, std::size_t bytes) noexcept { munmap(pointer, roundUp(bytes, pageSize())); }

#else

void* mapAligned(std::size_t bytes) {
  void* pointer = std::aligned_alloc(kHugePage, roundUp(bytes, kHugePage));
  if (pointer == nullptr) throw std::bad_alloc();
  return pointer;
}

void unmapAligned(void* pointer, std::size_t) noexcept { std::free(pointer); }

#endif

}  // namespace

void* allocateLargeArray(std::size_t bytes) { return bytes < kHugePage ? ::operator new(bytes) : mapAligned(bytes); }

void freeLargeArray(void* pointer, std::size_t bytes) noexcept {
  if (bytes < kHugePage)
    ::operator delete(pointer);
  else
    unmapAligned(pointer, bytes);
}

}  // namespace lrsvo
