#pragma once

#include "lrsvo/graph/autodiff_edge.h"
#include "lrsvo/vertices/so3.h"
#include "lrsvo/vertices/vertex_bal_camera.h"
#include "lrsvo/vertices/vertex_point3.h"

namespace lrsvo {

// The BAL (Snavely) reprojection: P = R(w) X + t, p = -P / P_z,
// prediction = f (1 + k1 |p|^2 + k2 |p|^4) p; residual = prediction - measurement.
// Analytic Jacobians for camera and point.
class EdgeBalProjection : public AutoDiffEdge<EdgeBalProjection, 2, VertexBalCamera, VertexPoint3> {
 public:
  static constexpr const char* kTypeTag = "BAL_PROJECTION";
  const char* typeTag() const override { return kTypeTag; }
  template <typename T>
  void residual(const Eigen::Matrix<T, 9, 1>& camera, const Eigen::Matrix<T, 3, 1>& point,
                Eigen::Matrix<T, 2, 1>& r) const {
    const Eigen::Matrix<T, 3, 1> P =
        rotateByAngleAxis<T>(camera.template head<3>(), point) + camera.template segment<3>(3);
    const Eigen::Matrix<T, 2, 1> p = -P.template head<2>() / P.z();
    const T r2 = p.squaredNorm();
    const T distortion = 1.0 + r2 * (camera[7] + camera[8] * r2);
    r = camera[6] * distortion * p - measurement_.cast<T>();
  }
  void computeJacobians() override;
};

// Rotates x by the angle-axis vector w (Rodrigues), as the BAL format defines.
Eigen::Vector3d angleAxisRotate(const Eigen::Vector3d& w, const Eigen::Vector3d& x);

// Its dual-number code is compiled once, in its source file.
extern template class AutoDiffEdge<EdgeBalProjection, 2, VertexBalCamera, VertexPoint3>;

}  // namespace lrsvo
