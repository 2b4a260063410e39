#include <cmath>

#include <gtest/gtest.h>

#include "lrsvo/frontend/odometry/motion_model.h"
#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

// A camera moving at 3 m/s along a tilted direction while turning at 0.2 rad/s
// about one of its own axes: its pose at t.
Eigen::Isometry3d steadyMotion(double t) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = (Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(0.2 * t, Eigen::Vector3d(1.0, 2.0, -0.5).normalized()))
                      .toRotationMatrix();
  pose.translation() = Eigen::Vector3d(10.0, -4.0, 100.0) + t * Eigen::Vector3d(2.4, 1.8, 0.0);
  return pose;
}

TEST(ConstantVelocity, PredictsAConstantMotionExactly) {
  ConstantVelocity motion(0.5);
  for (int i = 0; i <= 30; ++i) motion.add(i / 30.0, steadyMotion(i / 30.0));
  for (double t : {1.0, 1.5, 3.0}) {
    const Eigen::Isometry3d predicted = motion.predict(t), truth = steadyMotion(t);
    EXPECT_LT((predicted.translation() - truth.translation()).norm(), 1e-9) << t;
    EXPECT_LT(Eigen::AngleAxisd(predicted.linear().transpose() * truth.linear()).angle(), 1e-9) << t;
  }
}

// The velocity is differenced over the span, not the last frame: a last pose
// off by 1 cm moves a prediction one span (0.5 s) ahead by 2 cm (its own
// offset, and 1 cm over the 0.5 s span carried 0.5 s), not by the 16 cm a
// one-frame difference would give (1 cm over 1/30 s, carried 0.5 s, plus 1 cm).
TEST(ConstantVelocity, VelocityIsDifferencedOverItsSpan) {
  ConstantVelocity motion(0.5);
  for (int i = 0; i <= 30; ++i) {
    Eigen::Isometry3d pose = steadyMotion(i / 30.0);
    if (i == 30) pose.translation().x() += 0.01;
    motion.add(i / 30.0, pose);
  }
  const double error = (motion.predict(1.5).translation() - steadyMotion(1.5).translation()).norm();
  EXPECT_NEAR(error, 0.02, 1e-6);
}

TEST(ConstantVelocity, OnePoseIsHeldAndNoneIsAnError) {
  ConstantVelocity motion;
  EXPECT_FALSE(motion.known());
  EXPECT_THROW(motion.predict(0.0), Error);
  motion.add(2.0, steadyMotion(2.0));
  EXPECT_TRUE(motion.predict(5.0).isApprox(steadyMotion(2.0)));
  EXPECT_THROW(motion.add(1.0, steadyMotion(1.0)), Error);
}

}  // namespace
}  // namespace lrsvo
