// Automatic differentiation (graph/autodiff_edge.h): every edge type's
// hand-written Jacobians against its dual-number ones, and an edge that has
// nothing but a templated residual, on a manifold vertex.
//
// Tolerance: the analytic and the dual-number Jacobian compute the same
// derivative in double, each through a few hundred roundings of relative size
// 2^-53 = 1.1e-16 on terms no larger than the column they produce (the
// projections here are well conditioned: depth over 1 m, angles below pi).
// Their difference is then below ~1e-13 |J| + 1e-13; 1e-12 relative and
// absolute leaves a factor of ten.

#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "lrsvo/constraints/barrier_edge.h"
#include "lrsvo/constraints/constraint_types.h"
#include "lrsvo/edges/edge_bal_projection.h"
#include "lrsvo/edges/edge_centre_distance.h"
#include "lrsvo/edges/edge_extrinsic_rate_prior.h"
#include "lrsvo/edges/edge_project_base.h"
#include "lrsvo/edges/edge_project_held_view.h"
#include "lrsvo/edges/edge_project_secondary.h"
#include "lrsvo/edges/edge_project_secondary_drifting.h"
#include "lrsvo/edges/edge_scale_prior.h"
#include "lrsvo/edges/edge_se2.h"
#include "lrsvo/edges/edge_se3_quat.h"
#include "lrsvo/edges/edge_types.h"
#include "lrsvo/graph/autodiff_edge.h"
#include "lrsvo/graph/registry.h"
#include "lrsvo/vertices/so3.h"
#include "unit_tests/graph/test_problems.h"

namespace lrsvo::test {
namespace {

constexpr double kTolerance = 1e-12;
constexpr int kTrials = 100;

Eigen::Vector3d gaussian3(std::mt19937_64& rng, double sigma) {
  std::normal_distribution<double> n(0.0, sigma);
  return {n(rng), n(rng), n(rng)};
}

// A long-range stereo state: a camera ~100 m above a point, a deformed 0.7 m rig.
struct StereoState {
  VertexPose pose{0};
  VertexPoint3 point{1};
  VertexStereoExtrinsic extrinsic{2};
  VertexScale scale{3};
  VertexExtrinsicRate rate{4};
  PinholeIntrinsics intrinsics{1670.0, 1660.0, 640.0, 480.0};

  explicit StereoState(std::mt19937_64& rng) {
    std::normal_distribution<double> n(0.0, 1.0);
    Eigen::Isometry3d cameraFromWorld = Eigen::Isometry3d::Identity();
    cameraFromWorld.linear() = expSO3(gaussian3(rng, 1.0));
    cameraFromWorld.translation() = gaussian3(rng, 50.0);
    pose.setCameraFromWorld(cameraFromWorld);
    const Eigen::Vector3d inCamera(10 * n(rng), 10 * n(rng), 100.0 + 10 * n(rng));
    point.setEstimateVector(cameraFromWorld.inverse() * inCamera);
    VertexStereoExtrinsic::Vector6 s;
    s << 0.01 * n(rng), 0.7 + 0.01 * n(rng), 0.01 * n(rng), 0.05 * n(rng), 0.05 * n(rng), 0.05 * n(rng);
    extrinsic.setEstimateVector(s);
    scale.setEstimateVector(Eigen::Matrix<double, 1, 1>(0.5 + std::abs(n(rng))));
    VertexExtrinsicRate::Vector6 r;
    for (double& value : r) value = 0.01 * n(rng);
    rate.setEstimateVector(r);
  }
};

template <typename EdgeType>
void expectAutoDiffMatches(EdgeType& edge, int trial) {
  EXPECT_TRUE(jacobiansMatchAutoDiff(edge, kTolerance, kTolerance)) << "trial " << trial;
}

TEST(AutoDiff, StereoProjectionEdgesMatchTheirAnalyticJacobians) {
  std::mt19937_64 rng(21);
  for (int trial = 0; trial < kTrials; ++trial) {
    StereoState s(rng);
    EdgeProjectBase base(s.intrinsics);
    base.setVertex(0, &s.pose);
    base.setVertex(1, &s.point);
    expectAutoDiffMatches(base, trial);

    EdgeProjectSecondary secondary(SecondaryCamera{1, s.intrinsics});
    secondary.setVertex(0, &s.pose);
    secondary.setVertex(1, &s.point);
    secondary.setVertex(2, &s.extrinsic);
    expectAutoDiffMatches(secondary, trial);

    EdgeProjectSecondaryScaled scaled(SecondaryCamera{1, s.intrinsics});
    scaled.setVertex(0, &s.pose);
    scaled.setVertex(1, &s.point);
    scaled.setVertex(2, &s.extrinsic);
    scaled.setVertex(3, &s.scale);
    expectAutoDiffMatches(scaled, trial);

    EdgeProjectSecondaryDrifting drifting(SecondaryCamera{2, s.intrinsics}, 0.1 * trial);
    drifting.setVertex(0, &s.pose);
    drifting.setVertex(1, &s.point);
    drifting.setVertex(2, &s.extrinsic);
    drifting.setVertex(3, &s.rate);
    expectAutoDiffMatches(drifting, trial);
  }
}

TEST(AutoDiff, HeldViewAndPriorEdgesMatchTheirAnalyticJacobians) {
  std::mt19937_64 rng(22);
  for (int trial = 0; trial < kTrials; ++trial) {
    StereoState s(rng);
    const Eigen::Vector3d origin = gaussian3(rng, 20.0);
    EdgeProjectHeldView held(s.intrinsics, s.pose.cameraFromWorld(), origin);
    held.setVertex(0, &s.point);
    held.setVertex(1, &s.scale);
    expectAutoDiffMatches(held, trial);

    VertexPose other(5);
    Eigen::Isometry3d otherPose = s.pose.cameraFromWorld();
    otherPose.translation() += gaussian3(rng, 5.0);
    otherPose.linear() = expSO3(gaussian3(rng, 0.3)) * otherPose.linear();
    other.setCameraFromWorld(otherPose);
    EdgeCentreDistance distance;
    distance.setVertex(0, &s.pose);
    distance.setVertex(1, &other);
    distance.setMeasurement(Eigen::Matrix<double, 1, 1>(3.0));
    expectAutoDiffMatches(distance, trial);

    EdgeScalePrior scalePrior;
    scalePrior.setVertex(0, &s.scale);
    expectAutoDiffMatches(scalePrior, trial);

    EdgeExtrinsicRatePrior ratePrior;
    ratePrior.setVertex(0, &s.rate);
    expectAutoDiffMatches(ratePrior, trial);
  }
}

TEST(AutoDiff, BalProjectionMatchesItsAnalyticJacobians) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> focal(300.0, 1500.0), k1(-0.2, 0.2), k2(-0.05, 0.05), angle(0.0, 3.0);
  for (int trial = 0; trial < kTrials; ++trial) {
    // The identity and tiny rotations too, where Rodrigues' formula switches to its series.
    Eigen::Vector3d w = gaussian3(rng, 1.0).normalized() * angle(rng);
    if (trial == 0) w.setZero();
    if (trial == 1) w *= 1e-9 / w.norm();
    if (trial == 2) w *= 1e-3 / w.norm();  // just above the series' range
    const Eigen::Vector3d t = gaussian3(rng, 3.0);
    Eigen::Matrix<double, 9, 1> parameters;
    parameters << w, t, focal(rng), k1(rng), k2(rng);
    VertexBalCamera camera(0);
    camera.setEstimateVector(parameters);
    const Eigen::Vector3d lateral = gaussian3(rng, 0.5);
    const Eigen::Vector3d inCamera(-5.0 * lateral.x(), -5.0 * lateral.y(), -5.0);  // BAL looks down -z
    VertexPoint3 point(1, expSO3(w).transpose() * (inCamera - t));
    EdgeBalProjection edge;
    edge.setVertex(0, &camera);
    edge.setVertex(1, &point);
    expectAutoDiffMatches(edge, trial);
  }
}

TEST(AutoDiff, PoseGraphEdgesMatchTheirAnalyticJacobians) {
  std::mt19937_64 rng(26);
  std::uniform_real_distribution<double> heading(-3.1, 3.1);
  for (int trial = 0; trial < kTrials; ++trial) {
    VertexSE2 a(0, Eigen::Vector3d(gaussian3(rng, 5.0).x(), gaussian3(rng, 5.0).y(), heading(rng)));
    VertexSE2 b(1, Eigen::Vector3d(gaussian3(rng, 5.0).x(), gaussian3(rng, 5.0).y(), heading(rng)));
    EdgeSE2 planar;
    planar.setVertex(0, &a);
    planar.setVertex(1, &b);
    planar.setMeasurement(Eigen::Vector3d(gaussian3(rng, 1.0).x(), gaussian3(rng, 1.0).y(), heading(rng)));
    expectAutoDiffMatches(planar, trial);

    Eigen::Isometry3d from = Eigen::Isometry3d::Identity(), to = Eigen::Isometry3d::Identity(),
                      relative = Eigen::Isometry3d::Identity();
    from.linear() = expSO3(gaussian3(rng, 1.5));
    from.translation() = gaussian3(rng, 5.0);
    to.linear() = expSO3(gaussian3(rng, 1.5));
    to.translation() = gaussian3(rng, 5.0);
    relative.linear() = expSO3(gaussian3(rng, 1.5));
    relative.translation() = gaussian3(rng, 1.0);
    VertexSE3Quat c(2, from), d(3, to);
    EdgeSE3Quat spatial;
    spatial.setVertex(0, &c);
    spatial.setVertex(1, &d);
    spatial.setRelativePose(relative);
    expectAutoDiffMatches(spatial, trial);
  }
}

TEST(AutoDiff, FixedVerticesAreSkipped) {
  std::mt19937_64 rng(24);
  StereoState s(rng);
  s.pose.setFixed(true);
  EdgeProjectBase edge(s.intrinsics);
  edge.setVertex(0, &s.pose);
  edge.setVertex(1, &s.point);
  edge.jacobian<0>().setConstant(7.0);
  edge.computeAutoDiffJacobians();
  EXPECT_TRUE((edge.jacobian<0>().array() == 7.0).all());
  EXPECT_TRUE(jacobiansMatchAutoDiff(edge, kTolerance, kTolerance));
}

// A user's edge with no hand-written Jacobian: the bearing of a world point
// seen from a pose, r = (R X + t) / |R X + t| - measurement.
class EdgeBearing : public AutoDiffEdge<EdgeBearing, 3, VertexPose, VertexPoint3> {
 public:
  const char* typeTag() const override { return "TEST_BEARING"; }
  template <typename T>
  void residual(const RigidState<T>& pose, const Eigen::Matrix<T, 3, 1>& point, Eigen::Matrix<T, 3, 1>& r) const {
    using std::sqrt;
    const Eigen::Matrix<T, 3, 1> ray = pose.rotation * point + pose.translation;
    r = ray / sqrt(ray.squaredNorm()) - measurement_.cast<T>();
  }
};

// Joins the bearing edge to the state's pose and point, with a random unit measurement.
void connectBearing(EdgeBearing& edge, StereoState& s, std::mt19937_64& rng) {
  edge.setVertex(0, &s.pose);
  edge.setVertex(1, &s.point);
  edge.setMeasurement(gaussian3(rng, 1.0).normalized());
}

// Central differences with step h = 1e-6 err by h^2 |r'''| / 6 + eps |r| / h:
// with |r'''| of order 1 / |ray|^3 and |r| <= 2 here, about 1e-10 and the
// columns' own rounding; 1e-7 is far above both and far below any wrong entry.
TEST(AutoDiff, AnEdgeWithOnlyATemplatedResidualMatchesCentralDifferences) {
  std::mt19937_64 rng(25);
  for (int trial = 0; trial < kTrials; ++trial) {
    StereoState s(rng);
    EdgeBearing edge;
    connectBearing(edge, s, rng);
    edge.computeJacobians();
    const Eigen::Matrix<double, 3, 6> autodiffPose = edge.jacobian<0>();
    const Eigen::Matrix<double, 3, 3> autodiffPoint = edge.jacobian<1>();
    edge.computeNumericJacobians();
    EXPECT_LT((autodiffPose - edge.jacobian<0>()).cwiseAbs().maxCoeff(), 1e-7) << "trial " << trial;
    EXPECT_LT((autodiffPoint - edge.jacobian<1>()).cwiseAbs().maxCoeff(), 1e-7) << "trial " << trial;
  }
}

// A linearisation of an edge with only a templated residual evaluates it once,
// in dual numbers: their values are the residual. They come from the same
// operations as the double path (Dual's value arithmetic is double's), so they
// agree to the rounding of a differently ordered sum in an Eigen kernel, a few
// units of 1.1e-16 |r|; 1e-14 |r| leaves a wide margin and catches any stale
// or wrong value (of order |r| itself).
TEST(AutoDiff, ALinearisationTakesTheResidualFromTheDualNumbers) {
  std::mt19937_64 rng(26);
  for (int trial = 0; trial < kTrials; ++trial) {
    StereoState s(rng);
    EdgeBearing edge;
    connectBearing(edge, s, rng);
    EdgeBearing::Residual fromDuals;
    EdgeBearing::Residual inDouble;
    edge.computeResidualAndJacobians(fromDuals);
    edge.computeResidual(inDouble);
    EXPECT_LE((fromDuals - inDouble).cwiseAbs().maxCoeff(), 1e-14 * inDouble.norm()) << "trial " << trial;
    const Eigen::Matrix<double, 3, 6> poseJacobian = edge.jacobian<0>();
    edge.computeAutoDiffJacobians();
    EXPECT_EQ(poseJacobian, edge.jacobian<0>()) << "trial " << trial;
  }
}

// An edge with hand-written Jacobians keeps them in a linearisation, and its
// residual is the double path's, never the values of an earlier dual-number
// evaluation at another state.
TEST(AutoDiff, ALinearisationUsesHandWrittenJacobiansAndTheCurrentResidual) {
  std::mt19937_64 rng(27);
  StereoState s(rng);
  EdgeProjectBase edge(s.intrinsics);
  edge.setVertex(0, &s.pose);
  edge.setVertex(1, &s.point);
  edge.setMeasurement(Eigen::Vector2d(600.0, 500.0));
  edge.computeAutoDiffJacobians();
  s.point.setEstimateVector(s.point.estimate() + Eigen::Vector3d(1.0, -2.0, 0.5));
  EdgeProjectBase::Residual linearised;
  EdgeProjectBase::Residual current;
  edge.computeResidualAndJacobians(linearised);
  edge.computeResidual(current);
  EXPECT_EQ(linearised, current);
  const Eigen::Matrix<double, 2, 6> poseJacobian = edge.jacobian<0>();
  edge.computeJacobians();
  EXPECT_EQ(poseJacobian, edge.jacobian<0>());
}

// The tests above must cover every least-squares edge type the library
// registers. The bound barrier is a cost edge with an exact Hessian of its own,
// not a residual.
TEST(AutoDiff, EveryRegisteredEdgeTypeIsCovered) {
  registerEdgeTypes();
  registerConstraintTypes();
  const std::set<std::string> covered = {EdgeBalProjection::kTypeTag,
                                         EdgeCentreDistance::kTypeTag,
                                         EdgeExtrinsicRatePrior::kTypeTag,
                                         EdgeProjectBase::kTypeTag,
                                         EdgeProjectHeldView::kTypeTag,
                                         EdgeProjectSecondary::kTypeTag,
                                         EdgeProjectSecondaryScaled::kTypeTag,
                                         EdgeProjectSecondaryDrifting::kTypeTag,
                                         EdgeScalePrior::kTypeTag,
                                         EdgeSE2::kTypeTag,
                                         EdgeSE3Quat::kTypeTag};
  for (const auto& [tag, entry] : Registry<Edge>::instance().entries()) {
    if (tag.rfind("TEST_", 0) == 0 || tag == BarrierEdge::kTypeTag) continue;  // other tests' own types
    EXPECT_TRUE(covered.count(tag)) << tag << " has no automatic-differentiation check";
  }
}

}  // namespace
}  // namespace lrsvo::test
