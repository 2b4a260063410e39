#pragma once

#include <Eigen/Geometry>

#include "lrsvo/graph/vertex.h"

namespace lrsvo {

// The angle wrapped into (-pi, pi].
double wrapAngle(double angle);

// A planar pose, world-from-body, as g2o's VERTEX_SE2: position (x, y) and
// heading theta. Update delta = (dx, dy, dtheta) adds to each, the heading
// wrapped into (-pi, pi]. The estimate is kept as given (a heading outside
// that range too), so a save/load round trip is exact.
class VertexSE2 : public BaseVertex<3> {
 public:
  static constexpr const char* kTypeTag = "POSE_SE2";
  explicit VertexSE2(int id = -1, const Eigen::Vector3d& pose = Eigen::Vector3d::Zero()) : BaseVertex<3>(id) {
    setPose(pose);
  }

  // (x, y, theta).
  const Eigen::Vector3d& pose() const { return pose_; }
  void setPose(const Eigen::Vector3d& pose) { pose_ = pose; }
  Eigen::Vector2d translation() const { return pose_.head<2>(); }
  double angle() const { return pose_[2]; }
  Eigen::Isometry2d worldFromBody() const;

  int estimateSize() const override { return 3; }
  void getEstimate(double* values) const override;
  // Throws lrsvo::Error when a value is not finite.
  void setEstimate(const double* values) override;
  void oplus(const double* delta) override;

  // For graph/autodiff_edge.h: (x, y, theta), and the same after oplus(delta)
  // in any scalar type (unwrapped: the same heading, and differentiable).
  const Eigen::Vector3d& state() const { return pose_; }
  template <typename T>
  Eigen::Matrix<T, 3, 1> perturbed(const Eigen::Matrix<T, 3, 1>& delta) const {
    return pose_.cast<T>() + delta;
  }
  const char* typeTag() const override { return kTypeTag; }
  std::unique_ptr<Vertex> clone() const override { return std::make_unique<VertexSE2>(*this); }

 private:
  Eigen::Vector3d pose_ = Eigen::Vector3d::Zero();
};

}  // namespace lrsvo
