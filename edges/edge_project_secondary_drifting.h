#pragma once

#include "lrsvo/edges/secondary_projection.h"
#include "lrsvo/graph/base_edge.h"
#include "lrsvo/vertices/vertex_extrinsic_rate.h"
#include "lrsvo/vertices/vertex_point3.h"

namespace lrsvo {

// Projection into secondary camera k >= 1 of a frame taken `dt_s` seconds
// after the extrinsic's reference time, through the extrinsic the window's
// S and its rate give then: s(t) = s + dt * rate, x = pi(K_k R_s(t) (R X + t - c(t))).
// With the rate at zero it is EdgeProjectSecondary.
class EdgeProjectSecondaryDrifting
    : public BaseEdge<2, VertexPose, VertexPoint3, VertexStereoExtrinsic, VertexExtrinsicRate> {
 public:
  static constexpr const char* kTypeTag = "PROJECT_SECONDARY_DRIFTING";
  EdgeProjectSecondaryDrifting() = default;
  EdgeProjectSecondaryDrifting(const SecondaryCamera& camera, double dt_s) : camera_(camera), dt_s_(dt_s) {}

  const char* typeTag() const override { return kTypeTag; }
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

}  // namespace lrsvo
