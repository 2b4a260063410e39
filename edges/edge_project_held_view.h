#pragma once

#include <Eigen/Geometry>

#include "lrsvo/edges/pinhole.h"
#include "lrsvo/graph/autodiff_edge.h"
#include "lrsvo/vertices/vertex_point3.h"
#include "lrsvo/vertices/vertex_scale.h"

namespace lrsvo {

// A base-camera observation from a held view (a keyframe retired from the
// sliding window) whose orientation is fixed and whose centre slides with the
// map's scale s about a fixed origin: C = origin + s * offset,
// x = pi(K R (X - C)). The held views keep the window's map from tilting (the
// long-range bas-relief ambiguity) without also fixing its scale, which the
// stereo observations keep estimating. Vertices: the point, and s. Analytic Jacobians.
class EdgeProjectHeldView : public AutoDiffEdge<EdgeProjectHeldView, 2, VertexPoint3, VertexScale> {
 public:
  static constexpr const char* kTypeTag = "PROJECT_HELD_VIEW";
  EdgeProjectHeldView() = default;
  // `cameraFromWorld` is the held view's pose at s = 1.
  EdgeProjectHeldView(const PinholeIntrinsics& intrinsics, const Eigen::Isometry3d& cameraFromWorld,
                      const Eigen::Vector3d& origin);

  // The held view's pose at scale s.
  Eigen::Isometry3d cameraFromWorld(double s) const;
  const char* typeTag() const override { return kTypeTag; }
  template <typename T>
  void residual(const Eigen::Matrix<T, 3, 1>& point, const Eigen::Matrix<T, 1, 1>& scale,
                Eigen::Matrix<T, 2, 1>& r) const {
    const Eigen::Matrix<T, 3, 1> centre = origin_.cast<T>() + scale[0] * offset_.cast<T>();
    const Eigen::Matrix<T, 3, 1> pointInCamera = rotation_.cast<T>() * (point - centre);
    r = intrinsics_.projectAs(pointInCamera) - measurement_.cast<T>();
  }
  void computeJacobians() override;

 protected:
  void writeParameters(std::ostream& out) const override;
  void readParameters(std::istream& in) override;

 private:
  PinholeIntrinsics intrinsics_;
  Eigen::Quaterniond quaternion_ = Eigen::Quaterniond::Identity();  // camera from world, as given (file I/O)
  Eigen::Matrix3d rotation_ = Eigen::Matrix3d::Identity();          // of quaternion_, for the solver's loops
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d offset_ = Eigen::Vector3d::Zero();  // the centre at s = 1, minus origin
};

// Its dual-number code is compiled once, in its source file.
extern template class AutoDiffEdge<EdgeProjectHeldView, 2, VertexPoint3, VertexScale>;

}  // namespace lrsvo
