#pragma once

#include <Eigen/Core>

namespace lrsvo {

// Skew-symmetric matrix [v]x with [v]x u = v x u.
Eigen::Matrix3d skew(const Eigen::Vector3d& v);
// Rotation matrix of an axis-angle vector (exponential map of SO(3)).
Eigen::Matrix3d expSO3(const Eigen::Vector3d& omega);
// Left Jacobian of SO(3): Exp(w + d) = Exp(J_l(w) d) Exp(w) to first order.
Eigen::Matrix3d leftJacobianSO3(const Eigen::Vector3d& omega);

}  // namespace lrsvo
