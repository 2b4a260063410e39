#pragma once

#include <cstddef>
#include <vector>

namespace lrsvo {

// Storage for arrays of megabytes (the Hessian's blocks and their edge lists):
// on Linux, mapped from the system on a 2 MiB boundary with transparent huge
// pages requested for each whole 2 MiB of the array (madvise), so that the
// first touch of a new array faults once per 2 MiB instead of once per 4 KiB
// page. Each solve allocates these afresh, and on a virtual machine a page
// fault can cost more than the work done on the page. The partial last 2 MiB
// takes small pages, so no array holds more than a page it does not use, and
// a freed array returns to the system at once. Arrays under 2 MiB come from
// operator new.
void* allocateLargeArray(std::size_t bytes);
void freeLargeArray(void* pointer, std::size_t bytes) noexcept;

template <typename T>
struct LargeArrayAllocator {
  using value_type = T;
  LargeArrayAllocator() = default;
  template <typename U>
  LargeArrayAllocator(const LargeArrayAllocator<U>&) noexcept {}
  T* allocate(std::size_t n) { return static_cast<T*>(allocateLargeArray(n * sizeof(T))); }
  void deallocate(T* pointer, std::size_t n) noexcept { freeLargeArray(pointer, n * sizeof(T)); }
  template <typename U>
  bool operator==(const LargeArrayAllocator<U>&) const noexcept {
    return true;
  }
};

template <typename T>
using LargeArray = std::vector<T, LargeArrayAllocator<T>>;

}  // namespace lrsvo
