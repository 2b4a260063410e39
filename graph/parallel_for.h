#pragma once

#include <algorithm>

#include "lrsvo/graph/thread_pool.h"

namespace lrsvo {

// Runs body(i) for i in [begin, end) on up to `threads` threads (the caller's
// and ThreadPool's workers), handing out itemsPerChunk iterations at a time
// (fewer for a few costly iterations, so that every thread gets some; 1 for
// iterations of very different cost). Iterations must write to disjoint
// memory. The first exception an iteration throws is rethrown once the loop
// is done. lrsvo's one parallel loop: the solver's and the renderer's.
template <typename Body>
void parallelFor(int begin, int end, int threads, int itemsPerChunk, const Body& body) {
  if (end <= begin) return;
  const int chunkSize = std::max(1, itemsPerChunk);
  struct Loop {
    const Body& body;
    int begin, end, chunkSize;
  } loop{body, begin, end, chunkSize};
  const ThreadPool::Task task{&loop, [](const void* object, int chunk) {
                                const Loop& l = *static_cast<const Loop*>(object);
                                const int first = l.begin + chunk * l.chunkSize;
                                const int last = std::min(l.end, first + l.chunkSize);
                                for (int i = first; i < last; ++i) l.body(i);
                              }};
  ThreadPool::instance().run((end - begin + chunkSize - 1) / chunkSize, threads, task);
}

// The same, 64 iterations at a time: for many cheap iterations.
template <typename Body>
void parallelFor(int begin, int end, int threads, const Body& body) {
  parallelFor(begin, end, threads, 64, body);
}

}  // namespace lrsvo
