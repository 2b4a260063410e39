#pragma once

#include "lrsvo/graph/base_edge.h"
#include "lrsvo/vertices/vertex_se2.h"

namespace lrsvo {

// A relative planar pose between vertices i (slot 0) and j (slot 1), as g2o's
// EDGE_SE2. The measurement Z = (dx, dy, dtheta) is pose j seen from pose i;
// the residual is the pose of Z^-1 (X_i^-1 X_j) as (x, y, theta), theta
// wrapped into (-pi, pi]:
//   r_t = Rz^T (Ri^T (t_j - t_i) - t_z),  r_theta = wrap(theta_j - theta_i - theta_z).
class EdgeSE2 : public BaseEdge<3, VertexSE2, VertexSE2> {
 public:
  static constexpr const char* kTypeTag = "RELATIVE_POSE_SE2";
  const char* typeTag() const override { return kTypeTag; }
  void computeResidual(Residual& residual) const override;
  void computeJacobians() override;
};

}  // namespace lrsvo
