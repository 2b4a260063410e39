#pragma once

#include "lrsvo/graph/base_edge.h"
#include "lrsvo/vertices/vertex_pose.h"

namespace lrsvo {

// A prior on the distance between two camera centres: r = |C_b - C_a| - d,
// d the measurement. With a large information it fixes the scale gauge of a
// monocular map (docs/method.md, long-range initialisation: the first pair at unit
// distance) while leaving both poses' rotations and the direction of travel
// free, which fixing the second pose outright would not.
class EdgeCentreDistance : public BaseEdge<1, VertexPose, VertexPose> {
 public:
  static constexpr const char* kTypeTag = "CENTRE_DISTANCE";
  const char* typeTag() const override { return kTypeTag; }
  void computeResidual(Residual& residual) const override;
  void computeJacobians() override;
};

}  // namespace lrsvo
