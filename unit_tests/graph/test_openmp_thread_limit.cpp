// The OpenMP limit a solver holds around CHOLMOD and Eigen: one thread runs
// even a region that asks for four serially, more threads set the region size
// and dynamic adjustment, and the caller's settings come back afterwards.
#include <algorithm>

#include <gtest/gtest.h>
#include <omp.h>

#include "lrsvo/graph/openmp_thread_limit.h"

namespace lrsvo::test {
namespace {

// The team size of a region that asks for `requested` threads, as CHOLMOD's do.
int teamSize(int requested) {
  int size = 0;
#pragma omp parallel num_threads(requested)
  {
#pragma omp single
    size = omp_get_num_threads();
  }
  return size;
}

struct CallerSettings {
  int maxActiveLevels;
  int maxThreads;
  int dynamic;
};

CallerSettings currentSettings() { return {omp_get_max_active_levels(), omp_get_max_threads(), omp_get_dynamic()}; }

class OpenMpThreadLimitTest : public ::testing::Test {
 protected:
  void SetUp() override {
    saved_ = currentSettings();
    omp_set_max_active_levels(3);
    omp_set_num_threads(5);
    omp_set_dynamic(0);
  }
  void TearDown() override {
    omp_set_max_active_levels(saved_.maxActiveLevels);
    omp_set_num_threads(saved_.maxThreads);
    omp_set_dynamic(saved_.dynamic);
  }
  static void expectCallerSettings() {
    const CallerSettings now = currentSettings();
    EXPECT_EQ(now.maxActiveLevels, 3);
    EXPECT_EQ(now.maxThreads, 5);
    EXPECT_EQ(now.dynamic, 0);
  }

 private:
  CallerSettings saved_{};
};

TEST_F(OpenMpThreadLimitTest, OneThreadRunsARegionOfFourSerially) {
  {
    const OpenMpThreadLimit limit(1);
    EXPECT_EQ(teamSize(4), 1);
  }
  expectCallerSettings();
}

TEST_F(OpenMpThreadLimitTest, MoreThreadsSetTheRegionSizeAndLetTheRuntimeShrinkIt) {
  {
    const OpenMpThreadLimit limit(2);
    EXPECT_EQ(omp_get_max_threads(), 2);
    EXPECT_NE(omp_get_dynamic(), 0);
    // Dynamic adjustment never gives a region more threads than processors.
    const int size = teamSize(4);
    EXPECT_GE(size, 1);
    EXPECT_LE(size, std::min(4, omp_get_num_procs()));
  }
  expectCallerSettings();
}

}  // namespace
}  // namespace lrsvo::test
