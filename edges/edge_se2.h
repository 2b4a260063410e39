#pragma once

#include <cmath>

#include "lrsvo/graph/autodiff_edge.h"
#include "lrsvo/vertices/vertex_se2.h"

namespace lrsvo {

// A relative planar pose between vertices i (slot 0) and j (slot 1), as g2o's
// EDGE_SE2. The measurement Z = (dx, dy, dtheta) is pose j seen from pose i;
// the residual is the pose of Z^-1 (X_i^-1 X_j) as (x, y, theta), theta
// wrapped into (-pi, pi]:
//   r_t = Rz^T (Ri^T (t_j - t_i) - t_z),  r_theta = wrap(theta_j - theta_i - theta_z).
// Analytic Jacobians.
class EdgeSE2 : public AutoDiffEdge<EdgeSE2, 3, VertexSE2, VertexSE2> {
 public:
  static constexpr const char* kTypeTag = "RELATIVE_POSE_SE2";
  const char* typeTag() const override { return kTypeTag; }
  template <typename T>
  void residual(const Eigen::Matrix<T, 3, 1>& from, const Eigen::Matrix<T, 3, 1>& to, Eigen::Matrix<T, 3, 1>& r) const {
    using std::atan2;
    using std::cos;
    using std::sin;
    const T c = cos(from[2]), s = sin(from[2]);
    const T dx = to[0] - from[0], dy = to[1] - from[1];
    const T ex = c * dx + s * dy - measurement_[0], ey = -s * dx + c * dy - measurement_[1];
    const double cz = std::cos(measurement_[2]), sz = std::sin(measurement_[2]);
    const T angle = to[2] - from[2] - measurement_[2];
    // The wrap as atan2(sin, cos): into (-pi, pi], and smooth for dual numbers.
    r << cz * ex + sz * ey, -sz * ex + cz * ey, atan2(sin(angle), cos(angle));
  }
  void computeJacobians() override;
};

// Its dual-number code is compiled once, in its source file.
extern template class AutoDiffEdge<EdgeSE2, 3, VertexSE2, VertexSE2>;

}  // namespace lrsvo
