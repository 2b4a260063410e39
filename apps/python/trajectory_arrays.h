#pragma once

#include <Eigen/Core>

#include "lrsvo/frontend/datasets/pose_file.h"

namespace lrsvo::python {

// A trajectory as an N x 8 array in the TUM layout: t, x, y, z, qx, qy, qz, qw
// (world-from-camera). From an array the quaternions are normalised as the
// TUM reader does; lrsvo::Error on a wrong shape, a non-finite value or a
// zero quaternion.
using TrajectoryArray = Eigen::Matrix<double, Eigen::Dynamic, 8, Eigen::RowMajor>;
TrajectoryArray toArray(const Trajectory& trajectory);
Trajectory fromArray(const Eigen::Ref<const Eigen::MatrixXd>& array, const char* what);

}  // namespace lrsvo::python
