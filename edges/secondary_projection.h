#pragma once

#include <limits>

#include "lrsvo/edges/pinhole.h"
#include "lrsvo/vertices/vertex_pose.h"
#include "lrsvo/vertices/vertex_stereo_extrinsic.h"

namespace lrsvo {

// x = pi(K_k R_s (R X + t - c / kappa)) (docs/method.md, eq. 5), in any scalar
// type. Returns NaN pixels when kappa <= 0, so a solver rejects such a step.
template <typename T>
Eigen::Matrix<T, 2, 1> projectSecondary(const RigidState<T>& pose, const Eigen::Matrix<T, 3, 1>& point,
                                        const ExtrinsicState<T>& extrinsic, const T& kappa,
                                        const PinholeIntrinsics& intrinsics) {
  if (!(kappa > 0.0)) return Eigen::Matrix<T, 2, 1>::Constant(T(std::numeric_limits<double>::quiet_NaN()));
  const Eigen::Matrix<T, 3, 1> base = pose.rotation * point + pose.translation;
  const Eigen::Matrix<T, 3, 1> offset = base - extrinsic.parameters.template head<3>() / kappa;
  const Eigen::Matrix<T, 3, 1> secondary = extrinsic.rotation * offset;
  return intrinsics.projectAs(secondary);
}

// Derivatives of a secondary camera's projection (docs/method.md, eq. 5).
struct SecondaryProjectionJacobians {
  Eigen::Matrix<double, 2, 6> pose;
  Eigen::Matrix<double, 2, 3> point;
  Eigen::Matrix<double, 2, 6> extrinsic;
  Eigen::Vector2d kappa;
};

// The analytic Jacobians of projectSecondary (kappa > 0).
SecondaryProjectionJacobians secondaryProjectionJacobians(const VertexPose& pose, const Eigen::Vector3d& point,
                                                          const VertexStereoExtrinsic& extrinsic, double kappa,
                                                          const PinholeIntrinsics& intrinsics);

// The data a secondary projection edge keeps in graph files: the camera
// index k >= 1 and that camera's intrinsics.
struct SecondaryCamera {
  int index = 1;
  PinholeIntrinsics intrinsics;
  void write(std::ostream& out) const;
  void read(std::istream& in, const char* what);
};

}  // namespace lrsvo
