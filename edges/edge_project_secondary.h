#pragma once

#include "lrsvo/edges/secondary_projection.h"
#include "lrsvo/graph/autodiff_edge.h"
#include "lrsvo/vertices/vertex_point3.h"
#include "lrsvo/vertices/vertex_scale.h"

namespace lrsvo {

// Projection into secondary camera k >= 1 through its extrinsic, shared by
// every pose of the window (docs/method.md, eq. 5 with kappa = 1):
// x = pi(K_k R_s (R X + t - c)). Analytic Jacobians.
class EdgeProjectSecondary
    : public AutoDiffEdge<EdgeProjectSecondary, 2, VertexPose, VertexPoint3, VertexStereoExtrinsic> {
 public:
  static constexpr const char* kTypeTag = "PROJECT_SECONDARY";
  EdgeProjectSecondary() = default;
  explicit EdgeProjectSecondary(const SecondaryCamera& camera) : camera_(camera) {}

  const SecondaryCamera& camera() const { return camera_; }
  const char* typeTag() const override { return kTypeTag; }
  template <typename T>
  void residual(const RigidState<T>& pose, const Eigen::Matrix<T, 3, 1>& point, const ExtrinsicState<T>& extrinsic,
                Eigen::Matrix<T, 2, 1>& r) const {
    r = projectSecondary(pose, point, extrinsic, T(1.0), camera_.intrinsics) - measurement_.cast<T>();
  }
  void computeJacobians() override;

 protected:
  void writeParameters(std::ostream& out) const override { camera_.write(out); }
  void readParameters(std::istream& in) override { camera_.read(in, kTypeTag); }

 private:
  SecondaryCamera camera_;
};

// The same with the scale kappa of a monocular start as a fourth vertex:
// x = pi(K_k R_s (R X + t - c / kappa)) (docs/method.md, long-range initialisation).
class EdgeProjectSecondaryScaled
    : public AutoDiffEdge<EdgeProjectSecondaryScaled, 2, VertexPose, VertexPoint3, VertexStereoExtrinsic, VertexScale> {
 public:
  static constexpr const char* kTypeTag = "PROJECT_SECONDARY_SCALED";
  EdgeProjectSecondaryScaled() = default;
  explicit EdgeProjectSecondaryScaled(const SecondaryCamera& camera) : camera_(camera) {}

  const SecondaryCamera& camera() const { return camera_; }
  const char* typeTag() const override { return kTypeTag; }
  template <typename T>
  void residual(const RigidState<T>& pose, const Eigen::Matrix<T, 3, 1>& point, const ExtrinsicState<T>& extrinsic,
                const Eigen::Matrix<T, 1, 1>& scale, Eigen::Matrix<T, 2, 1>& r) const {
    r = projectSecondary(pose, point, extrinsic, scale[0], camera_.intrinsics) - measurement_.cast<T>();
  }
  void computeJacobians() override;

 protected:
  void writeParameters(std::ostream& out) const override { camera_.write(out); }
  void readParameters(std::istream& in) override { camera_.read(in, kTypeTag); }

 private:
  SecondaryCamera camera_;
};

// Its dual-number code is compiled once, in its source file.
extern template class AutoDiffEdge<EdgeProjectSecondary, 2, VertexPose, VertexPoint3, VertexStereoExtrinsic>;
extern template class AutoDiffEdge<EdgeProjectSecondaryScaled, 2, VertexPose, VertexPoint3, VertexStereoExtrinsic,
                                   VertexScale>;

}  // namespace lrsvo
