#pragma once

#include <cmath>

#include "lrsvo/graph/autodiff_edge.h"
#include "lrsvo/vertices/vertex_pose.h"

namespace lrsvo {

// A prior on the distance between two camera centres: r = |C_b - C_a| - d,
// d the measurement. With a large information it fixes the scale gauge of a
// monocular map (docs/method.md, long-range initialisation: the first pair at unit
// distance) while leaving both poses' rotations and the direction of travel
// free, which fixing the second pose outright would not.
class EdgeCentreDistance : public AutoDiffEdge<EdgeCentreDistance, 1, VertexPose, VertexPose> {
 public:
  static constexpr const char* kTypeTag = "CENTRE_DISTANCE";
  const char* typeTag() const override { return kTypeTag; }
  template <typename T>
  void residual(const RigidState<T>& a, const RigidState<T>& b, Eigen::Matrix<T, 1, 1>& r) const {
    using std::sqrt;
    // C = -R^T t
    const Eigen::Matrix<T, 3, 1> difference =
        a.rotation.transpose() * a.translation - b.rotation.transpose() * b.translation;
    r[0] = sqrt(difference.squaredNorm()) - measurement_[0];
  }
  void computeJacobians() override;
};

// Its dual-number code is compiled once, in its source file.
extern template class AutoDiffEdge<EdgeCentreDistance, 1, VertexPose, VertexPose>;

}  // namespace lrsvo
