#pragma once

#include "lrsvo/edges/secondary_projection.h"
#include "lrsvo/graph/base_edge.h"
#include "lrsvo/vertices/vertex_point3.h"
#include "lrsvo/vertices/vertex_scale.h"

namespace lrsvo {

// Projection into secondary camera k >= 1 through its extrinsic, shared by
// every pose of the window (docs/method.md, eq. 5 with kappa = 1):
// x = pi(K_k R_s (R X + t - c)).
class EdgeProjectSecondary : public BaseEdge<2, VertexPose, VertexPoint3, VertexStereoExtrinsic> {
 public:
  static constexpr const char* kTypeTag = "PROJECT_SECONDARY";
  EdgeProjectSecondary() = default;
  explicit EdgeProjectSecondary(const SecondaryCamera& camera) : camera_(camera) {}

  const SecondaryCamera& camera() const { return camera_; }
  const char* typeTag() const override { return kTypeTag; }
  void computeResidual(Residual& residual) const override;
  void computeJacobians() override;

 protected:
  void writeParameters(std::ostream& out) const override { camera_.write(out); }
  void readParameters(std::istream& in) override { camera_.read(in, kTypeTag); }

 private:
  SecondaryCamera camera_;
};

// The same with the scale kappa of a monocular start as a fourth vertex:
// x = pi(K_k R_s (R X + t - c / kappa)) (docs/method.md, long-range initialisation).
class EdgeProjectSecondaryScaled : public BaseEdge<2, VertexPose, VertexPoint3, VertexStereoExtrinsic, VertexScale> {
 public:
  static constexpr const char* kTypeTag = "PROJECT_SECONDARY_SCALED";
  EdgeProjectSecondaryScaled() = default;
  explicit EdgeProjectSecondaryScaled(const SecondaryCamera& camera) : camera_(camera) {}

  const SecondaryCamera& camera() const { return camera_; }
  const char* typeTag() const override { return kTypeTag; }
  void computeResidual(Residual& residual) const override;
  void computeJacobians() override;

 protected:
  void writeParameters(std::ostream& out) const override { camera_.write(out); }
  void readParameters(std::istream& in) override { camera_.read(in, kTypeTag); }

 private:
  SecondaryCamera camera_;
};

}  // namespace lrsvo
