#pragma once

#include "lrsvo/graph/autodiff_edge.h"
#include "lrsvo/vertices/vertex_scale.h"

namespace lrsvo {

// A Gaussian prior on a scale vertex: r = s - measurement (its information is
// 1 / sigma^2). The sliding window keeps the scale its held views carry near
// the previous windows' value with it, so one window's weak stereo evidence
// moves the scale a little rather than all the way.
class EdgeScalePrior : public AutoDiffEdge<EdgeScalePrior, 1, VertexScale> {
 public:
  static constexpr const char* kTypeTag = "SCALE_PRIOR";
  const char* typeTag() const override { return kTypeTag; }
  template <typename T>
  void residual(const Eigen::Matrix<T, 1, 1>& scale, Eigen::Matrix<T, 1, 1>& r) const {
    r = scale - measurement_.cast<T>();
  }
  void computeJacobians() override;
};

// Its dual-number code is compiled once, in its source file.
extern template class AutoDiffEdge<EdgeScalePrior, 1, VertexScale>;

}  // namespace lrsvo
