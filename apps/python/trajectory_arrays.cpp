#include "trajectory_arrays.h"

#include <string>

#include <Eigen/Geometry>

#include "lrsvo/graph/error.h"

namespace lrsvo::python {

TrajectoryArray toArray(const Trajectory& trajectory) {
  TrajectoryArray array(trajectory.size(), 8);
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    const Eigen::Isometry3d& pose = trajectory.worldFromCamera[i];
    const Eigen::Quaterniond q(pose.linear());
    array.row(i) << trajectory.times_s[i], pose.translation().transpose(), q.x(), q.y(), q.z(), q.w();
  }
  return array;
}

Trajectory fromArray(const Eigen::Ref<const Eigen::MatrixXd>& array, const char* what) {
  if (array.cols() != 8)
    throw Error(std::string(what) + ": a trajectory is an N x 8 array (t, x, y, z, qx, qy, qz, qw), got " +
                std::to_string(array.rows()) + " x " + std::to_string(array.cols()));
  if (!array.allFinite()) throw Error(std::string(what) + ": the trajectory holds a value that is not finite");
  Trajectory trajectory;
  for (Eigen::Index i = 0; i < array.rows(); ++i) {
    Eigen::Quaterniond q(array(i, 7), array(i, 4), array(i, 5), array(i, 6));
    if (q.norm() < 1e-6)
      throw Error(std::string(what) + ": row " + std::to_string(i) + " holds a zero quaternion, expected a unit one");
    q.normalize();
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = q.toRotationMatrix();
    pose.translation() = array.row(i).segment<3>(1).transpose();
    trajectory.add(array(i, 0), pose);
  }
  return trajectory;
}

}  // namespace lrsvo::python
