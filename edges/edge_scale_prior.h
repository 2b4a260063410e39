#pragma once

#include "lrsvo/graph/base_edge.h"
#include "lrsvo/vertices/vertex_scale.h"

namespace lrsvo {

// A Gaussian prior on a scale vertex: r = s - measurement (its information is
// 1 / sigma^2). The sliding window keeps the scale its held views carry near
// the previous windows' value with it, so one window's weak stereo evidence
// moves the scale a little rather than all the way.
class EdgeScalePrior : public BaseEdge<1, VertexScale> {
 public:
  static constexpr const char* kTypeTag = "SCALE_PRIOR";
  const char* typeTag() const override { return kTypeTag; }
  void computeResidual(Residual& residual) const override;
  void computeJacobians() override;
};

}  // namespace lrsvo
