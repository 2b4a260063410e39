#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "lrsvo/frontend/datasets/gtsam_stereo_vo.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/optimizer.h"

namespace lrsvo::test {
namespace {

const std::string kDirectory = std::string(LRSVO_SHARED_DATA) + "/gtsam_stereo_vo";

TEST(GtsamStereoVo, LoadsTheKittiProblem) {
  const StereoVoProblem problem = loadGtsamStereoVo(kDirectory);
  EXPECT_EQ(problem.poses.size(), 26u);
  EXPECT_EQ(problem.factorCount, 8189);
  EXPECT_EQ(problem.graph.edges().size(), 2u * 8189u);
  EXPECT_DOUBLE_EQ(problem.baseline, 0.537150588);
  EXPECT_TRUE(problem.poses.front()->fixed());
  EXPECT_TRUE(problem.extrinsic->fixed());
}

TEST(GtsamStereoVo, SolvesWithEverySparseAndSchurSolver) {
  double reference = -1.0;
  for (const char* solver : {"lm_schur_cholmod", "lm_schur_dense", "lm_cholmod"}) {
    StereoVoProblem problem = loadGtsamStereoVo(kDirectory);
    const SolverSummary summary = Optimizer(SolverOptions::fromName(solver)).optimize(problem.graph);
    EXPECT_TRUE(summary.converged()) << summary.briefReport();
    EXPECT_LT(summary.finalCost, 0.5 * summary.initialCost) << summary.briefReport();
    if (reference < 0) reference = summary.finalCost;
    EXPECT_NEAR(summary.finalCost, reference, 1e-6 * reference) << solver;
  }
}

TEST(GtsamStereoVo, MissingOrBadFilesAreNamed) {
  EXPECT_THROW(loadGtsamStereoVo("/nonexistent"), Error);
  const std::string dir = ::testing::TempDir() + "/bad_stereo_vo";
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/VO_calibration.txt") << "700 700 0.5 600 170 0.5\n";
  try {
    loadGtsamStereoVo(dir);
    FAIL() << "a skewed calibration loaded";
  } catch (const ParseError& error) {
    EXPECT_EQ(error.line(), 1);
    EXPECT_NE(std::string(error.what()).find("VO_calibration.txt"), std::string::npos);
  }
}

}  // namespace
}  // namespace lrsvo::test
