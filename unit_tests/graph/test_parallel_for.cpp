#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

#include "lrsvo/graph/parallel_for.h"

namespace lrsvo {
namespace {

// Counts how often each index of [begin, end) ran.
std::vector<int> runCounts(int begin, int end, int threads, int chunk) {
  std::vector<std::atomic<int>> counts(static_cast<std::size_t>(std::max(end, 1)));
  parallelFor(begin, end, threads, chunk, [&](int i) { ++counts[static_cast<std::size_t>(i)]; });
  std::vector<int> result;
  for (const auto& c : counts) result.push_back(c.load());
  return result;
}

TEST(ParallelFor, RunsEveryIndexOnceWhateverTheThreadsAndChunks) {
  for (int threads : {1, 2, 3, 8})
    for (int chunk : {1, 3, 64})
      for (int end : {0, 1, 2, 7, 100, 1001}) {
        const std::vector<int> counts = runCounts(0, end, threads, chunk);
        for (int i = 0; i < end; ++i)
          ASSERT_EQ(counts[static_cast<std::size_t>(i)], 1)
              << "index " << i << " of " << end << ", " << threads << " threads, chunks of " << chunk;
      }
  const std::vector<int> offset = runCounts(5, 50, 2, 4);
  for (int i = 0; i < 50; ++i) EXPECT_EQ(offset[static_cast<std::size_t>(i)], i < 5 ? 0 : 1) << i;
}

TEST(ParallelFor, ManyShortLoopsInARowEachFinishBeforeReturning) {
  std::vector<int> values(37);
  for (int round = 1; round <= 5000; ++round) {
    parallelFor(0, 37, 2, 1, [&](int i) { values[static_cast<std::size_t>(i)] = round; });
    for (int v : values) ASSERT_EQ(v, round) << "round " << round;
  }
}

TEST(ParallelFor, RethrowsTheFirstExceptionAfterTheOtherIterationsRan) {
  std::atomic<int> ran{0};
  EXPECT_THROW(parallelFor(0, 100, 2, 1,
                           [&](int i) {
                             ++ran;
                             if (i == 10) throw std::runtime_error("iteration 10");
                           }),
               std::runtime_error);
  EXPECT_EQ(ran.load(), 100);
  int after = 0;  // the pool still serves loops
  parallelFor(0, 10, 2, 1, [&](int) {});
  parallelFor(0, 10, 1, 1, [&](int) { ++after; });
  EXPECT_EQ(after, 10);
}

TEST(ParallelFor, ALoopInsideALoopRunsOnItsThread) {
  std::vector<std::atomic<int>> counts(20 * 30);
  parallelFor(0, 20, 2, 1,
              [&](int i) { parallelFor(0, 30, 2, 1, [&](int j) { ++counts[static_cast<std::size_t>(30 * i + j)]; }); });
  for (const auto& c : counts) EXPECT_EQ(c.load(), 1);
}

TEST(ParallelFor, LoopsFromTwoThreadsAtOnceBothComplete) {
  std::vector<long> sums(2, 0);
  auto work = [&](int who) {
    for (int round = 0; round < 200; ++round) {
      std::vector<long> part(50, 0);
      parallelFor(0, 50, 2, 1, [&](int i) { part[static_cast<std::size_t>(i)] = i; });
      for (long v : part) sums[static_cast<std::size_t>(who)] += v;
    }
  };
  std::thread first(work, 0), second(work, 1);
  first.join();
  second.join();
  EXPECT_EQ(sums[0], 200L * 49 * 50 / 2);
  EXPECT_EQ(sums[1], 200L * 49 * 50 / 2);
}

}  // namespace
}  // namespace lrsvo
