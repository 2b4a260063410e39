#pragma once

#include "lrsvo/edges/pinhole.h"
#include "lrsvo/graph/autodiff_edge.h"
#include "lrsvo/vertices/vertex_point3.h"
#include "lrsvo/vertices/vertex_pose.h"

namespace lrsvo {

// Projection into the base camera (k = 0), docs/method.md, eq. 1:
// x = pi(K0 (R X + t)); residual = x - measurement, in pixels. Analytic Jacobians.
class EdgeProjectBase : public AutoDiffEdge<EdgeProjectBase, 2, VertexPose, VertexPoint3> {
 public:
  static constexpr const char* kTypeTag = "PROJECT_BASE";
  EdgeProjectBase() = default;
  explicit EdgeProjectBase(const PinholeIntrinsics& intrinsics) : intrinsics_(intrinsics) {}

  const PinholeIntrinsics& intrinsics() const { return intrinsics_; }
  const char* typeTag() const override { return kTypeTag; }
  template <typename T>
  void residual(const RigidState<T>& pose, const Eigen::Matrix<T, 3, 1>& point, Eigen::Matrix<T, 2, 1>& r) const {
    const Eigen::Matrix<T, 3, 1> pointInCamera = pose.rotation * point + pose.translation;
    r = intrinsics_.projectAs(pointInCamera) - measurement_.cast<T>();
  }
  void computeJacobians() override;

 protected:
  void writeParameters(std::ostream& out) const override { intrinsics_.write(out); }
  void readParameters(std::istream& in) override { intrinsics_.read(in, kTypeTag); }

 private:
  PinholeIntrinsics intrinsics_;
};

// Its dual-number code is compiled once, in its source file.
extern template class AutoDiffEdge<EdgeProjectBase, 2, VertexPose, VertexPoint3>;

}  // namespace lrsvo
