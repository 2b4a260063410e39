#pragma once

#include "lrsvo/graph/base_edge.h"
#include "lrsvo/vertices/vertex_bal_camera.h"
#include "lrsvo/vertices/vertex_point3.h"

namespace lrsvo {

// The BAL (Snavely) reprojection: P = R(w) X + t, p = -P / P_z,
// prediction = f (1 + k1 |p|^2 + k2 |p|^4) p; residual = prediction - measurement.
// Analytic Jacobians for camera and point.
class EdgeBalProjection : public BaseEdge<2, VertexBalCamera, VertexPoint3> {
 public:
  static constexpr const char* kTypeTag = "BAL_PROJECTION";
  const char* typeTag() const override { return kTypeTag; }
  void computeResidual(Residual& residual) const override;
  void computeJacobians() override;
};

// Rotates x by the angle-axis vector w (Rodrigues), as the BAL format defines.
Eigen::Vector3d angleAxisRotate(const Eigen::Vector3d& w, const Eigen::Vector3d& x);

}  // namespace lrsvo
