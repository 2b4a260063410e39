#pragma once

#include "lrsvo/graph/autodiff_edge.h"
#include "lrsvo/vertices/vertex_extrinsic_rate.h"

namespace lrsvo {

// A Gaussian prior on an extrinsic's rate: r = rate - measurement, with the
// information diag(1 / sigma^2) of how fast the rig may flex. A window sees
// its rate through small differences between its keyframes' stereo rays;
// the prior keeps noise from passing for flex.
class EdgeExtrinsicRatePrior : public AutoDiffEdge<EdgeExtrinsicRatePrior, 6, VertexExtrinsicRate> {
 public:
  static constexpr const char* kTypeTag = "STEREO_EXTRINSIC_RATE_PRIOR";
  const char* typeTag() const override { return kTypeTag; }
  template <typename T>
  void residual(const Eigen::Matrix<T, 6, 1>& rate, Eigen::Matrix<T, 6, 1>& r) const {
    r = rate - measurement_.cast<T>();
  }
  void computeJacobians() override;
};

// Its dual-number code is compiled once, in its source file.
extern template class AutoDiffEdge<EdgeExtrinsicRatePrior, 6, VertexExtrinsicRate>;

}  // namespace lrsvo
