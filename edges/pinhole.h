#pragma once

#include <iosfwd>

#include <Eigen/Core>

namespace lrsvo {

// Pinhole intrinsics of one camera (images undistorted before matching).
struct PinholeIntrinsics {
  double fx = 1.0, fy = 1.0, cx = 0.0, cy = 0.0;

  Eigen::Vector2d project(const Eigen::Vector3d& pointInCamera) const { return projectAs<double>(pointInCamera); }
  // The same in any scalar type (automatic differentiation).
  template <typename T>
  Eigen::Matrix<T, 2, 1> projectAs(const Eigen::Matrix<T, 3, 1>& p) const {
    return {fx * p.x() / p.z() + cx, fy * p.y() / p.z() + cy};
  }
  // d project / d pointInCamera.
  Eigen::Matrix<double, 2, 3> projectJacobian(const Eigen::Vector3d& p) const {
    const double iz = 1.0 / p.z();
    Eigen::Matrix<double, 2, 3> j;
    j << fx * iz, 0.0, -fx * p.x() * iz * iz, 0.0, fy * iz, -fy * p.y() * iz * iz;
    return j;
  }
  void write(std::ostream& out) const;
  // Throws lrsvo::Error on missing, non-finite or non-positive focal lengths.
  void read(std::istream& in, const char* what);
};

}  // namespace lrsvo
