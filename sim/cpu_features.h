#pragma once

// The renderer's four-wide paths: built for any x86-64 (the libraries are not
// compiled for AVX2), their functions ask for AVX2 alone (LRSVO_AVX2) and run
// only where cpuHasAvx2() finds it at run time. Without FMA the compiler
// cannot fuse a multiply and an add, so every operation rounds as the scalar
// paths' do and images are the same on every CPU.
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define LRSVO_AVX2 __attribute__((target("avx2")))
#endif

namespace lrsvo {

inline bool cpuHasAvx2() {
#ifdef LRSVO_AVX2
  static const bool hasAvx2 = __builtin_cpu_supports("avx2");
  return hasAvx2;
#else
  return false;
#endif
}

}  // namespace lrsvo
