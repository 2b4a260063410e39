#pragma once

#include "lrsvo/edges/pinhole.h"
#include "lrsvo/vertices/vertex_pose.h"
#include "lrsvo/vertices/vertex_stereo_extrinsic.h"

namespace lrsvo {

// Derivatives of a secondary camera's projection (docs/method.md, eq. 5).
struct SecondaryProjectionJacobians {
  Eigen::Matrix<double, 2, 6> pose;
  Eigen::Matrix<double, 2, 3> point;
  Eigen::Matrix<double, 2, 6> extrinsic;
  Eigen::Vector2d kappa;
};

// x = pi(K_k R_s (R X + t - c / kappa)). Writes the Jacobians when asked.
// Returns NaN pixels when kappa <= 0, so a solver rejects such a step.
Eigen::Vector2d projectSecondary(const VertexPose& pose, const Eigen::Vector3d& point,
                                 const VertexStereoExtrinsic& extrinsic, double kappa,
                                 const PinholeIntrinsics& intrinsics, SecondaryProjectionJacobians* jacobians);

// The data a secondary projection edge keeps in graph files: the camera
// index k >= 1 and that camera's intrinsics.
struct SecondaryCamera {
  int index = 1;
  PinholeIntrinsics intrinsics;
  void write(std::ostream& out) const;
  void read(std::istream& in, const char* what);
};

}  // namespace lrsvo
