#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "lrsvo/eval/deformed_pair.h"
#include "lrsvo/eval/depth_resolution.h"
#include "lrsvo/eval/line_rig.h"
#include "lrsvo/eval/paper_cameras.h"
#include "lrsvo/eval/sample_statistics.h"
#include "lrsvo/eval/triangulation_trials.h"
#include "lrsvo/frontend/features/epipolar.h"
#include "lrsvo/frontend/odometry/triangulation.h"
#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

constexpr double kDegree = M_PI / 180.0;

TEST(DepthResolution, HandComputedAtFigureOneSettings) {
  // f b = 1200 * 0.7 = 840 px m; at Z = 100 m, d = 8.4 px.
  EXPECT_DOUBLE_EQ(disparity_px(1200.0, 0.7, 100.0), 8.4);
  EXPECT_NEAR(depthStepExact_m(1200.0, 0.7, 100.0), 840.0 / 7.4 - 100.0, 1e-12);   // 13.51 m
  EXPECT_NEAR(depthStepNearer_m(1200.0, 0.7, 100.0), 100.0 - 840.0 / 9.4, 1e-12);  // 10.64 m
  EXPECT_NEAR(depthStepFirstOrder_m(1200.0, 0.7, 100.0), 10000.0 / 840.0, 1e-12);  // 11.90 m
  EXPECT_TRUE(std::isinf(depthStepExact_m(1200.0, 0.1, 200.0)));                   // d = 0.6 px: no pixel less to go
  EXPECT_THROW(disparity_px(1200.0, 0.0, 10.0), Error);
}

TEST(PaperCameras, FocalLengthOfTheOptics) {
  EXPECT_DOUBLE_EQ(paperOpticsFocal_px(), 6.0 * 1024.0 / 4.8);  // 1280 px
  EXPECT_DOUBLE_EQ(paperIntrinsics(860.0).cx, 512.0);
  EXPECT_DOUBLE_EQ(paperIntrinsics(860.0).cy, 384.0);
}

TEST(Epipolar, FundamentalMatrixHoldsForProjectionsOfAnyPoint) {
  const PinholeIntrinsics k0{900.0, 910.0, 320.0, 240.0}, k1{1000.0, 990.0, 330.0, 250.0};
  const VertexStereoExtrinsic::Vector6 s =
      (VertexStereoExtrinsic::Vector6() << 0.3, -0.1, 0.05, 0.02, -0.03, 0.01).finished();
  const Eigen::Isometry3d secondary = secondaryFromBase(s);
  const Eigen::Matrix3d f = fundamentalMatrix(k0, k1, secondary);
  for (const Eigen::Vector3d& point : {Eigen::Vector3d(1.0, 2.0, 20.0), Eigen::Vector3d(-3.0, 0.5, 7.0)}) {
    const Eigen::Vector2d x0 = k0.project(point), x1 = k1.project(secondary * point);
    EXPECT_NEAR(epipolarDistance(f, x0, x1), 0.0, 1e-9);
    EXPECT_GT(epipolarDistance(f, x0, x1 + Eigen::Vector2d(3.0, 3.0)), 0.1);
  }
}

TEST(DeformedPair, CalibratedPairHasNoErrors) {
  const VertexStereoExtrinsic::Vector6 calibration = verticalPairCalibration(0.7);
  const DeformedPairErrors e =
      deformedPairErrors(paperIntrinsics(1280.0), calibration, calibration, Eigen::Vector3d(0.0, 0.0, 100.0));
  EXPECT_NEAR(e.epipolar_px, 0.0, 1e-9);
  EXPECT_NEAR(e.triangulation_m, 0.0, 1e-6);
  EXPECT_NEAR(e.triangulatedDepth_m, 100.0, 1e-6);
}

TEST(DeformedPair, EpipolarErrorOfHandComputedDeformations) {
  // Vertical rig, epipolar lines are columns. A rotation delta about y turns the
  // secondary's view of (0, -b, Z) to (Z sin delta, -b, Z cos delta): u - cx = f tan delta.
  const PinholeIntrinsics k = paperIntrinsics(1000.0);
  const VertexStereoExtrinsic::Vector6 c = verticalPairCalibration(0.7);
  const Eigen::Vector3d point(0.0, 0.0, 100.0);
  auto epipolar = [&](DeformationKind kind, int axis, double amount) {
    return deformedPairErrors(k, c, deformedExtrinsic(c, {kind, axis, amount}), point).epipolar_px;
  };
  EXPECT_NEAR(epipolar(DeformationKind::kRotation, 1, 0.2 * kDegree), 1000.0 * std::tan(0.2 * kDegree), 1e-9);
  // A shift of the centre by t across the baseline moves the image by f t / Z; along it, along the column.
  EXPECT_NEAR(epipolar(DeformationKind::kTranslation, 0, 0.05), 1000.0 * 0.05 / 100.0, 1e-9);
  EXPECT_NEAR(epipolar(DeformationKind::kTranslation, 1, 0.05), 0.0, 1e-9);
  // A rotation about x moves the image along the column: no epipolar error.
  EXPECT_NEAR(epipolar(DeformationKind::kRotation, 0, 0.2 * kDegree), 0.0, 1e-9);
}

TEST(DeformedPair, TriangulationErrorOfARotationAboutX) {
  // Rx(t) (0, -b, Z) = (0, -b cos t - Z sin t, Z cos t - b sin t): with the
  // calibrated baseline the disparity gives Z' = b (Z cos t - b sin t) / (b cos t + Z sin t).
  const double b = 0.7, z = 100.0;
  const VertexStereoExtrinsic::Vector6 c = verticalPairCalibration(b);
  for (double t : {0.2 * kDegree, -0.2 * kDegree}) {
    const double expected = b * (z * std::cos(t) - b * std::sin(t)) / (b * std::cos(t) + z * std::sin(t));
    for (double f : {860.0, 1280.0}) {  // without noise f drops out
      const DeformedPairErrors e = deformedPairErrors(
          paperIntrinsics(f), c, deformedExtrinsic(c, {DeformationKind::kRotation, 0, t}), Eigen::Vector3d(0, 0, z));
      EXPECT_NEAR(e.triangulatedDepth_m, expected, 1e-6 * expected);
      EXPECT_NEAR(e.triangulation_m, std::abs(expected - z), 1e-6 * expected);
    }
  }
}

TEST(DeformedPair, NegativeDisparityGivesNoPoint) {
  // -0.5 deg about x moves the image 11 px against a disparity of 9 px.
  const VertexStereoExtrinsic::Vector6 c = verticalPairCalibration(0.7);
  const DeformedPairErrors e = deformedPairErrors(paperIntrinsics(1280.0), c,
                                                  deformedExtrinsic(c, {DeformationKind::kRotation, 0, -0.5 * kDegree}),
                                                  Eigen::Vector3d(0.0, 0.0, 100.0));
  EXPECT_TRUE(std::isnan(e.triangulation_m));
  EXPECT_THROW(deformedExtrinsic(c, {DeformationKind::kRotation, 3, 0.1}), Error);
}

TEST(DeformedPair, SweepCoversBothSignsOfEveryAxis) {
  const std::vector<Deformation> sweep = deformationSweep(0.1, 0.01, 5);
  ASSERT_EQ(sweep.size(), 2u * 3u * 11u);
  EXPECT_DOUBLE_EQ(sweep.front().amount, -0.1);
  EXPECT_DOUBLE_EQ(sweep[5].amount, 0.0);
  EXPECT_EQ(sweep.back().kind, DeformationKind::kRotation);
  EXPECT_EQ(sweep.back().axis, 2);
  EXPECT_DOUBLE_EQ(sweep.back().amount, 0.01);
}

TEST(LineRig, ClosedFormEqualsFrontendTriangulationOnRandomCases) {
  std::mt19937_64 random(42);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 1.0);
  int compared = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const int cameras = 2 + trial % 4;
    const LineRig rig =
        LineRig::evenlySpaced(paperIntrinsics(800.0 + 600.0 * uniform(random)), cameras, 0.2 + 0.8 * uniform(random));
    const Eigen::Vector3d point(20.0 * (uniform(random) - 0.5), 20.0 * (uniform(random) - 0.5),
                                10.0 + 60.0 * uniform(random));
    std::vector<Eigen::Vector2d> pixels;
    for (int k = 0; k < cameras; ++k)
      pixels.push_back(rig.project(k, point) + Eigen::Vector2d(noise(random), noise(random)));
    const std::optional<Eigen::Vector3d> closedForm = triangulateOnLine(rig, pixels);
    TriangulationOptions options;
    options.maxIterations = 50;
    const TriangulationResult general = triangulate(rig.views(pixels), options);
    ASSERT_EQ(closedForm.has_value(), general.valid);
    if (!closedForm) continue;
    ++compared;
    EXPECT_NEAR((*closedForm - general.point).norm(), 0.0, 1e-6 * point.norm()) << "trial " << trial;
  }
  EXPECT_GT(compared, 50);
}

TEST(LineRig, ExactWithoutNoiseAndNoPointForNegativeDisparity) {
  const LineRig rig = LineRig::evenlySpaced(paperIntrinsics(1280.0), 3, 0.7);
  EXPECT_DOUBLE_EQ(rig.centres_m[0], -0.7);
  EXPECT_DOUBLE_EQ(rig.centres_m[2], 0.7);
  const Eigen::Vector3d point(1.0, -2.0, 80.0);
  std::vector<Eigen::Vector2d> pixels;
  for (int k = 0; k < 3; ++k) pixels.push_back(rig.project(k, point));
  EXPECT_NEAR((*triangulateOnLine(rig, pixels) - point).norm(), 0.0, 1e-9);
  std::swap(pixels[0], pixels[2]);  // the disparity's sign flips
  EXPECT_FALSE(triangulateOnLine(rig, pixels).has_value());
  EXPECT_THROW(triangulateOnLine(rig, std::vector<Eigen::Vector2d>(2)), Error);
}

TEST(TriangulationTrials, SeededAndCountingFailures) {
  const LineRig rig = LineRig::evenlySpaced(paperIntrinsics(1280.0), 2, 0.2);
  const Eigen::Vector3d point(0.0, 0.0, 100.0);  // disparity 2.56 px, noise sqrt(2) px on it
  const TriangulationTrials a = runTriangulationTrials(rig, point, 1.0, 2000, 5, 1);
  const TriangulationTrials b = runTriangulationTrials(rig, point, 1.0, 2000, 5, 1);
  const TriangulationTrials c = runTriangulationTrials(rig, point, 1.0, 2000, 5, 2);
  EXPECT_EQ(a.depths_m, b.depths_m);
  EXPECT_NE(a.depths_m, c.depths_m);
  EXPECT_EQ(a.count(), 2000);
  // P(disparity <= 0) = Phi(-2.56 / sqrt 2) = 3.5 %: some, not many.
  EXPECT_GT(a.failed, 20);
  EXPECT_LT(a.failed, 150);
  const TriangulationTrials exact = runTriangulationTrials(rig, point, 0.0, 3, 5, 1);
  for (double e : exact.errors_m) EXPECT_NEAR(e, 0.0, 1e-9);
}

TEST(SampleStatistics, MomentsAndOrderStatisticsOfAHandSample) {
  const std::vector<double> values{4.0, 1.0, 10.0, 2.0, 3.0};
  // Deviations from 4: -3 -2 -1 0 6; m2 = 10, m3 = 36, m4 = 278.8.
  const Moments m = sampleMoments(values);
  EXPECT_DOUBLE_EQ(m.mean, 4.0);
  EXPECT_DOUBLE_EQ(m.stddev, std::sqrt(10.0));
  EXPECT_NEAR(m.skewness, 36.0 / std::pow(10.0, 1.5), 1e-12);
  EXPECT_NEAR(m.excessKurtosis, 278.8 / 100.0 - 3.0, 1e-12);
  const SortedSample sorted(values);
  EXPECT_DOUBLE_EQ(sorted.median(), 3.0);
  EXPECT_DOUBLE_EQ(sorted.quantile(0.25), 2.0);
  EXPECT_DOUBLE_EQ(sorted.quantile(0.125), 1.5);
  EXPECT_DOUBLE_EQ(sorted.quartileSkewness(), 0.0);  // Q1 2, Q2 3, Q3 4
  EXPECT_THROW(SortedSample({}), Error);
  EXPECT_TRUE(std::isnan(sampleMoments({}).mean));
}

TEST(SampleStatistics, HalfSampleModeFindsTheDensestHalf) {
  // Halves of 3: [2, 2.25, 2.5] is the narrowest; then its middle is equidistant.
  EXPECT_DOUBLE_EQ(SortedSample({9.0, 1.0, 2.25, 5.0, 2.0, 2.5}).halfSampleMode(), 2.25);
  EXPECT_DOUBLE_EQ(SortedSample({1.0, 1.5, 7.0}).halfSampleMode(), 1.25);
  EXPECT_DOUBLE_EQ(SortedSample({3.0}).halfSampleMode(), 3.0);
}

TEST(SampleStatistics, HistogramCountsInsideAndOutside) {
  const Histogram h = makeHistogram(std::vector<double>{-1.0, 0.0, 0.5, 1.99, 2.0, 3.0}, 0.0, 2.0, 2);
  EXPECT_EQ(h.counts, (std::vector<long>{2, 1}));
  EXPECT_EQ(h.below, 1);
  EXPECT_EQ(h.above, 2);
  EXPECT_DOUBLE_EQ(h.binCentre(1), 1.5);
  EXPECT_THROW(makeHistogram(std::vector<double>{}, 1.0, 1.0, 3), Error);
}

}  // namespace
}  // namespace lrsvo
