#pragma once

namespace lrsvo {

// Runs body(i) for i in [begin, end) on up to `threads` OpenMP threads.
// Iterations must write to disjoint memory.
template <typename Body>
void parallelFor(int begin, int end, int threads, const Body& body) {
#pragma omp parallel for num_threads(threads) schedule(dynamic, 64) if (threads > 1)
  for (int i = begin; i < end; ++i) body(i);
}

}  // namespace lrsvo
