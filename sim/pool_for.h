#pragma once

#include <opencv2/core.hpp>

namespace lrsvo {

// body(i) for every i in [begin, end): with threads > 1 on OpenCV's thread
// pool (its size is OpenCV's, cv::getNumThreads()), each i a task of its
// own; with threads <= 1 in order on the calling thread. Iterations must
// write to disjoint memory and must not throw.
//
// Why not OpenMP (graph/parallel_for.h): the renderer runs between the front
// end's OpenCV calls (KLT, stereo matching). OpenMP's idle threads spin for
// a while after each parallel region, and on 2 cores that spinning beside
// OpenCV's own pool made KLT take two thirds longer (`lrsvo bench run`,
// docs/simulator.md).
// On the pool OpenCV itself uses, the two never compete.
template <typename Body>
void poolFor(int begin, int end, int threads, const Body& body) {
  if (threads <= 1 || end - begin <= 1) {
    for (int i = begin; i < end; ++i) body(i);
    return;
  }
  cv::parallel_for_(
      cv::Range(begin, end),
      [&](const cv::Range& range) {
        for (int i = range.start; i < range.end; ++i) body(i);
      },
      end - begin);
}

}  // namespace lrsvo
