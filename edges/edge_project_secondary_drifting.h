#pragma once

#include "lrsvo/edges/secondary_projection.h"
#include "lrsvo/graph/autodiff_edge.h"
#include "lrsvo/vertices/vertex_extrinsic_rate.h"
#include "lrsvo/vertices/vertex_point3.h"

namespace lrsvo {

// Projection into secondary camera k >= 1 of a frame taken `dt_s` seconds
// after the extrinsic's reference time, through the extrinsic the window's
// S and its rate give then: s(t) = s + dt * rate, x = pi(K_k R_s(t) (R X + t - c(t))).
// With the rate at zero it is EdgeProjectSecondary. Analytic Jacobians.
class EdgeProjectSecondaryDrifting : public AutoDiffEdge<EdgeProjectSecondaryDrifting, 2, VertexPose, VertexPoint3,
                                                         VertexStereoExtrinsic, VertexExtrinsicRate> {
 public:
  static constexpr const char* kTypeTag = "PROJECT_SECONDARY_DRIFTING";
  EdgeProjectSecondaryDrifting() = default;
  EdgeProjectSecondaryDrifting(const SecondaryCamera& camera, double dt_s) : camera_(camera), dt_s_(dt_s) {}

  const char* typeTag() const override { return kTypeTag; }
  template <typename T>
  void residual(const RigidState<T>& pose, const Eigen::Matrix<T, 3, 1>& point, const ExtrinsicState<T>& extrinsic,
                const Eigen::Matrix<T, 6, 1>& rate, Eigen::Matrix<T, 2, 1>& r) const {
    const auto now = ExtrinsicState<T>::fromParameters(extrinsic.parameters + dt_s_ * rate);
    r = projectSecondary(pose, point, now, T(1.0), camera_.intrinsics) - measurement_.cast<T>();
  }
  // The residual above, with S(t) from the per-thread cache.
  void computeResidual(Residual& residual) const override;
  void computeJacobians() override;

 protected:
  void writeParameters(std::ostream& out) const override;
  void readParameters(std::istream& in) override;

 private:
  // S at this frame's time.
  const VertexStereoExtrinsic& extrinsicNow() const;

  SecondaryCamera camera_;
  double dt_s_ = 0.0;
};

// Its dual-number code is compiled once, in its source file.
extern template class AutoDiffEdge<EdgeProjectSecondaryDrifting, 2, VertexPose, VertexPoint3, VertexStereoExtrinsic,
                                   VertexExtrinsicRate>;

}  // namespace lrsvo
