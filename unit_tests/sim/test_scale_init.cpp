#include <cmath>
#include <cstdio>
#include <map>

#include <gtest/gtest.h>

#include "lrsvo/constraints/constraint_method.h"
#include "lrsvo/sim/window_problem.h"

// The paper's Fig. 18 claim on a seeded initialisation window (docs/method.md,
// long-range initialisation): 10 frames at 70 m, 60 m flown at 30 m/s (one
// keyframe per 6.7 m), 500 points, 1 px noise, the deformed rig's extrinsic
// bounded (+-1 mm, +-0.01 rad, gradient projection), the map handed to BA at
// a wrong scale, the same budget of 50 LM iterations for every run.
//
// Measured (seed 1): with kappa every start reaches kappa * startScale =
// 0.9703 (5-11 iterations); without kappa the map scale ends at 0.426 (from
// 0.25, budget used up), 0.9994 (0.5), 0.9993 (0.75), 0.9967 (1.0), 1.238
// (1.25), 1.482 (1.5). Over seeds 1-8 (100 iterations) with kappa every start
// gave the same scale per seed, 0.962-1.008; without kappa 0.25, 1.25 and 1.5
// never came within 10 % and 0.5 and 0.75 did for seed 1 only (the other
// seeds stayed at 0.50-0.88 and 0.75-0.77, i.e. near their start). So the
// claim holds, except that the basin without kappa is not a fixed +-10 %:
// the scale mostly stays where it started.
//
// Why: a rotation of the secondary camera about its y axis (pitch) shifts
// the disparity by f * pitch, 1.67 px per mrad, against 16.7 px of disparity
// at 70 m, and the +-0.01 rad box allows +-16.7 px. Without kappa a wrong
// map scale is absorbed by pitch (1.5 ends with the pitch 3.2 mrad off):
// the valley between pitch and scale is so flat that LM stops on its
// function tolerance at a cost above the optimum. With kappa, the baseline
// itself rescales, a direction well conditioned from any start. The same
// flat valley limits what the window can tell about scale: kappa's answer is
// a few per cent off (0.9703 with the pitch 0.31 mrad off, 0.31 * 1.67 px /
// 16.7 px = 3.1 %), hence the 5 % tolerance on the truth. A rigid rig with
// the extrinsic held at its (true) calibration is a different story: then
// both with and without kappa every start converges (measured 1.0039 and
// 0.9973 with 200 points), because the disparity pins the scale.

namespace lrsvo {
namespace {

constexpr double kStartScales[] = {0.25, 0.5, 0.75, 1.0, 1.25, 1.5};

WindowProblemOptions initialisationWindow(bool withScale, double startScale) {
  WindowProblemOptions options;
  options.frames = 10;
  options.altitude_m = 70.0;
  options.frameSpacing_m = 60.0 / 9.0;
  options.points = 500;
  options.withScale = withScale;  // kappa on every secondary edge; the first two poses fixed
  options.startScale = startScale;
  return options;
}

struct ScaleResult {
  double scale;  // the map's scale in the true unit after BA
  double finalCost;
  int iterations;
};

ScaleResult solveInitialisation(bool withScale, double startScale) {
  WindowProblem problem = makeWindowProblem(initialisationWindow(withScale, startScale));
  SolverOptions options;
  options.linearSolver = "schur_dense";
  options.maxIterations = 50;
  const SolverSummary summary =
      optimizeWithBounds(problem.graph, options, problem.extrinsicBounds, "gradient_projection");
  EXPECT_TRUE(problem.extrinsicBounds.hold());
  // With kappa the map stays in its start unit and kappa converts it to metres.
  const double scale = withScale ? problem.scale->kappa() * startScale : estimatedMapScale(problem);
  std::printf("  %-13s start scale %.2f -> %.4f, cost %.4e -> %.6e, %2d iterations (%s), %.2f s\n",
              withScale ? "with kappa" : "without kappa", startScale, scale, summary.initialCost, summary.finalCost,
              summary.iterationCount(), terminationName(summary.termination), summary.totalSeconds);
  return {scale, summary.finalCost, summary.iterationCount()};
}

TEST(ScaleInitialisation, WithKappaEveryStartScaleConvergesToTheTrueScale) {
  std::map<double, ScaleResult> results;
  for (double start : kStartScales) results[start] = solveInitialisation(true, start);
  const ScaleResult& reference = results[1.0];
  for (const auto& [start, result] : results) {
    EXPECT_NEAR(result.scale, 1.0, 0.05) << "start scale " << start;
    EXPECT_NEAR(result.scale, reference.scale, 0.005) << "start scale " << start << ": another solution";
    EXPECT_NEAR(result.finalCost, reference.finalCost, 1e-5 * reference.finalCost) << "start scale " << start;
    EXPECT_LT(result.iterations, 50) << "start scale " << start;
  }
}

TEST(ScaleInitialisation, WithoutKappaStartScalesFarFromOneAreNotRecovered) {
  const ScaleResult atOne = solveInitialisation(false, 1.0);
  EXPECT_NEAR(atOne.scale, 1.0, 0.01);
  for (double start : {0.25, 1.25, 1.5}) {
    const ScaleResult result = solveInitialisation(false, start);
    EXPECT_GT(std::abs(result.scale - 1.0), 0.1) << "start scale " << start << " reached the true scale";
    // Stuck in the pitch-scale valley, not at another optimum: the cost stays above the one near scale 1.
    EXPECT_GT(result.finalCost, atOne.finalCost * (1.0 + 1e-3)) << "start scale " << start;
  }
  // 0.5 and 0.75 do come back for this seed (though not for seeds 2-8, see above).
  for (double start : {0.5, 0.75}) EXPECT_NEAR(solveInitialisation(false, start).scale, 1.0, 0.01) << start;
}

}  // namespace
}  // namespace lrsvo
