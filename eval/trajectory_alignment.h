#pragma once

#include "lrsvo/frontend/datasets/pose_file.h"

namespace lrsvo {

// A similarity x -> scale * R x + t taking estimate coordinates to truth
// coordinates; `rigid` holds R and t, `scale` is 1 for a rigid (SE3) alignment.
struct Alignment {
  Eigen::Isometry3d rigid = Eigen::Isometry3d::Identity();
  double scale = 1.0;

  Eigen::Vector3d apply(const Eigen::Vector3d& x) const { return rigid.linear() * (scale * x) + rigid.translation(); }
};

enum class AlignmentKind { kSE3, kSim3 };

// Umeyama (1991): the rotation, translation (and for kSim3 the scale) that
// minimise sum_i |truth_i - (s R estimate_i + t)|^2 over the positions of
// pose-by-pose matched trajectories. Needs at least 2 poses (3 not on a line
// for a unique rotation); throws lrsvo::Error otherwise.
Alignment alignTrajectories(const Trajectory& estimate, const Trajectory& truth, AlignmentKind kind);

// The rigid transform that puts the first pose of `estimate` on the first pose of `truth`.
Alignment alignFirstPose(const Trajectory& estimate, const Trajectory& truth);

// `trajectory` moved by `alignment`: positions s R p + t, orientations R R_i.
Trajectory transformed(const Trajectory& trajectory, const Alignment& alignment);

}  // namespace lrsvo
