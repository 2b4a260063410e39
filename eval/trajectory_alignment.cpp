#include "lrsvo/eval/trajectory_alignment.h"

#include <Eigen/Geometry>

#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

Eigen::Matrix3Xd positions(const Trajectory& trajectory) {
  Eigen::Matrix3Xd p(3, static_cast<Eigen::Index>(trajectory.size()));
  for (std::size_t i = 0; i < trajectory.size(); ++i)
    p.col(static_cast<Eigen::Index>(i)) = trajectory.worldFromCamera[i].translation();
  return p;
}

void requireMatched(const Trajectory& estimate, const Trajectory& truth, std::size_t minimum, const char* what) {
  if (estimate.size() != truth.size())
    throw Error(std::string(what) + ": the trajectories are not matched pose by pose (" +
                std::to_string(estimate.size()) + " and " + std::to_string(truth.size()) + " poses)");
  if (estimate.size() < minimum)
    throw Error(std::string(what) + ": " + std::to_string(estimate.size()) + " matched poses, expected at least " +
                std::to_string(minimum));
}

}  // namespace

Alignment alignTrajectories(const Trajectory& estimate, const Trajectory& truth, AlignmentKind kind) {
  requireMatched(estimate, truth, 2, "alignment");
  const bool withScale = kind == AlignmentKind::kSim3;
  const Eigen::Matrix4d similarity = Eigen::umeyama(positions(estimate), positions(truth), withScale);
  Alignment alignment;
  alignment.scale = withScale ? similarity.block<3, 1>(0, 0).norm() : 1.0;
  alignment.rigid.linear() = similarity.topLeftCorner<3, 3>() / alignment.scale;
  alignment.rigid.translation() = similarity.topRightCorner<3, 1>();
  return alignment;
}

Alignment alignFirstPose(const Trajectory& estimate, const Trajectory& truth) {
  requireMatched(estimate, truth, 1, "start alignment");
  Alignment alignment;
  alignment.rigid = truth.worldFromCamera.front() * estimate.worldFromCamera.front().inverse();
  return alignment;
}

Trajectory transformed(const Trajectory& trajectory, const Alignment& alignment) {
  Trajectory moved;
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = alignment.rigid.linear() * trajectory.worldFromCamera[i].linear();
    pose.translation() = alignment.apply(trajectory.worldFromCamera[i].translation());
    moved.add(trajectory.times_s[i], pose);
  }
  return moved;
}

}  // namespace lrsvo
