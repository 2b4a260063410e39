#pragma once

namespace lrsvo {

// Runs body(i) for i in [begin, end) on up to `threads` OpenMP threads,
// handing out itemsPerChunk iterations at a time (fewer for a few costly
// iterations, so that every thread gets some). Iterations must write to
// disjoint memory.
template <typename Body>
void parallelFor(int begin, int end, int threads, int itemsPerChunk, const Body& body) {
#pragma omp parallel for num_threads(threads) schedule(dynamic, itemsPerChunk) if (threads > 1)
  for (int i = begin; i < end; ++i) body(i);
}

// The same, 64 iterations at a time: for many cheap iterations.
template <typename Body>
void parallelFor(int begin, int end, int threads, const Body& body) {
  parallelFor(begin, end, threads, 64, body);
}

}  // namespace lrsvo
