// Our stereo solvers against Ceres on the same model and start
// (apps/bench/ceres_stereo.h): the real KITTI problem and a window whose
// optimum lies outside the extrinsic's box.
#include <string>

#include <ceres/types.h>
#include <gtest/gtest.h>

#include "apps/bench/ceres_stereo.h"
#include "constraints/constraint_method.h"
#include "edges/gtsam_stereo_vo.h"
#include "graph/optimizer.h"
#include "sim/window_problem.h"

namespace lrsvo {
namespace {

const std::string kKittiDirectory = std::string(LRSVO_SHARED_DATA) + "/gtsam_stereo_vo";
constexpr double kModelTolerance = 1e-9;  // relative: initial costs of the same model
constexpr double kFinalTolerance = 1e-3;  // relative: final costs, 0.1 %

// Ceres' default tolerances (ours too), with room to converge.
SolverOptions stoppingRules(const std::string& solver) {
  SolverOptions options = SolverOptions::fromName(solver);
  options.maxIterations = 200;
  return options;
}

bool ceresConverged(const bench::SolveResult& result) {
  return result.termination == "function_tolerance" || result.termination == "gradient_tolerance" ||
         result.termination == "parameter_tolerance";
}

TEST(StereoVsCeres, ModelMatchesEveryEdgeTypeAndRobustKernel) {
  for (const char* kernel : {"", "Huber", "Cauchy", "Tukey"}) {
    WindowProblemOptions options;
    options.frames = 6;
    options.points = 60;
    options.maxTrackLength = 6;
    options.withScale = true;  // secondary edges with kappa
    options.startScale = 0.8;
    options.robustKernel = kernel;
    options.robustKernelDelta = 3.0;  // some residuals beyond it at this start
    const WindowProblem window = makeWindowProblem(options);
    bench::CeresStereoModel model(window.graph, window.extrinsicBounds);
    EXPECT_NEAR(model.cost(), window.graph.cost(), kModelTolerance * window.graph.cost()) << kernel;
  }
}

TEST(StereoVsCeres, KittiProblemReachesCeresFinalCost) {
  StereoVoProblem ours = loadGtsamStereoVo(kKittiDirectory);
  bench::CeresStereoModel ceresModel(ours.graph, Bounds{});
  const SolverOptions options = stoppingRules("lm_schur_cholmod");

  const SolverSummary summary = Optimizer(options).optimize(ours.graph);
  const bench::SolveResult ceres = ceresModel.solve(options, ceres::SPARSE_SCHUR);

  EXPECT_TRUE(summary.converged()) << summary.briefReport();
  EXPECT_TRUE(ceresConverged(ceres)) << ceres.termination;
  EXPECT_NEAR(ceres.initialCost, summary.initialCost, kModelTolerance * summary.initialCost);
  EXPECT_LT(summary.finalCost, 0.5 * summary.initialCost);
  EXPECT_NEAR(summary.finalCost, ceres.finalCost, kFinalTolerance * ceres.finalCost);

  // Ceres' solution costs in our graph what Ceres says it costs.
  StereoVoProblem atCeresSolution = loadGtsamStereoVo(kKittiDirectory);
  ceresModel.copyTo(atCeresSolution.graph);
  EXPECT_NEAR(atCeresSolution.graph.cost(), ceres.finalCost, kModelTolerance * ceres.finalCost);
}

TEST(StereoVsCeres, ActiveBoundsGradientProjectionReachesCeresFinalCost) {
  WindowProblemOptions options;
  options.trueOutsideBounds = true;  // roll above and yaw below their box
  WindowProblem ours = makeWindowProblem(options);
  bench::CeresStereoModel ceresModel(ours.graph, ours.extrinsicBounds);
  const SolverOptions stopping = stoppingRules("lm_schur_dense");

  const SolverSummary summary = optimizeWithBounds(ours.graph, stopping, ours.extrinsicBounds, "gradient_projection");
  const bench::SolveResult ceres = ceresModel.solve(stopping, ceres::DENSE_SCHUR);
  WindowProblem atCeresSolution = makeWindowProblem(options);
  ceresModel.copyTo(atCeresSolution.graph);
  {
    WindowProblem again = makeWindowProblem(options);
    ceresModel.copyTo(again.graph);
    const SolverSummary more = optimizeWithBounds(again.graph, stopping, again.extrinsicBounds, "gradient_projection");
    std::fprintf(stderr, "DEBUG ours from ceres: %s\n", more.briefReport().c_str());
    bench::CeresStereoModel fromOurs(ours.graph, ours.extrinsicBounds);
    const bench::SolveResult c2 = fromOurs.solve(stopping, ceres::DENSE_SCHUR);
    std::fprintf(stderr, "DEBUG ceres from ours: %d it %s %.9e -> %.9e\n", c2.iterations, c2.termination.c_str(), c2.initialCost, c2.finalCost);
    WindowProblem again2 = makeWindowProblem(options);
    bench::CeresStereoModel tight(again2.graph, again2.extrinsicBounds);
    SolverOptions t = stopping; t.functionTolerance = 1e-12; t.parameterTolerance=1e-14; t.maxIterations = 1000;
    const bench::SolveResult c3 = tight.solve(t, ceres::DENSE_SCHUR);
    std::fprintf(stderr, "DEBUG ceres tight: %d it %s %.9e -> %.9e\n", c3.iterations, c3.termination.c_str(), c3.initialCost, c3.finalCost);
    WindowProblem again3 = makeWindowProblem(options);
    const SolverSummary m3 = optimizeWithBounds(again3.graph, t, again3.extrinsicBounds, "gradient_projection");
    std::fprintf(stderr, "DEBUG ours tight: %s\n", m3.briefReport().c_str());
  }
  std::fprintf(stderr, "DEBUG ours %s\nceres %d it %s %.9e\n", summary.briefReport().c_str(), ceres.iterations, ceres.termination.c_str(), ceres.finalCost);
  std::fprintf(stderr, "DEBUG ours ext %s\n", ::testing::PrintToString(std::vector<double>(ours.extrinsic->estimate().data(), ours.extrinsic->estimate().data()+6)).c_str());
  std::fprintf(stderr, "DEBUG ceres ext %s\n", ::testing::PrintToString(std::vector<double>(atCeresSolution.extrinsic->estimate().data(), atCeresSolution.extrinsic->estimate().data()+6)).c_str());

  EXPECT_TRUE(summary.converged()) << summary.briefReport();
  EXPECT_TRUE(ceresConverged(ceres)) << ceres.termination;
  EXPECT_NEAR(ceres.initialCost, summary.initialCost, kModelTolerance * summary.initialCost);
  EXPECT_NEAR(summary.finalCost, ceres.finalCost, kFinalTolerance * ceres.finalCost);
  EXPECT_NEAR(atCeresSolution.graph.cost(), ceres.finalCost, kModelTolerance * ceres.finalCost);
  EXPECT_TRUE(ours.extrinsicBounds.hold());
  EXPECT_TRUE(atCeresSolution.extrinsicBounds.hold());
  // Both end on the two bounds the truth lies beyond (roll upper, yaw lower).
  for (const WindowProblem* solved : {&ours, &atCeresSolution}) {
    const auto& bounds = solved->extrinsicBounds.all();
    EXPECT_DOUBLE_EQ(Bounds::value(bounds[3]), bounds[3].upper);
    EXPECT_DOUBLE_EQ(Bounds::value(bounds[5]), bounds[5].lower);
  }
}

}  // namespace
}  // namespace lrsvo
