#include "lrsvo/frontend/odometry/rig.h"

#include <cmath>
#include <string>

#include "lrsvo/graph/error.h"

namespace lrsvo {

double focalLengthPixels(double lens_mm, double sensorWidth_mm, int imageWidth) {
  if (!(lens_mm > 0.0) || !(sensorWidth_mm > 0.0) || imageWidth <= 0)
    throw Error("focalLengthPixels: lens, sensor width and image width must be positive");
  return lens_mm * imageWidth / sensorWidth_mm;
}

double focalLengthFromFov(double horizontalFov_rad, int imageWidth) {
  if (!(horizontalFov_rad > 0.0 && horizontalFov_rad < M_PI) || imageWidth <= 0)
    throw Error("focalLengthFromFov: the field of view must lie in (0, pi) and the width be positive");
  return 0.5 * imageWidth / std::tan(0.5 * horizontalFov_rad);
}

Eigen::Isometry3d Rig::cameraFromWorld(const Eigen::Isometry3d& baseFromWorld, int camera) const {
  if (camera == 0) return baseFromWorld;
  return secondaryFromBase(extrinsics.at(camera - 1)) * baseFromWorld;
}

void Rig::addBounds(Bounds& bounds, Vertex* vertex, int camera) const {
  const VertexStereoExtrinsic::Vector6& p = extrinsics.at(camera - 1);
  for (int i = 0; i < 6; ++i) bounds.set(vertex, i, p[i] - tolerance[i], p[i] + tolerance[i]);
}

VertexStereoExtrinsic::Vector6 Rig::clampToBox(const VertexStereoExtrinsic::Vector6& s, int camera) const {
  const VertexStereoExtrinsic::Vector6& p = extrinsics.at(camera - 1);
  return s.cwiseMax(p - tolerance).cwiseMin(p + tolerance);
}

void Rig::validate() const {
  if (cameras.empty()) throw Error("rig: no camera");
  if (extrinsics.size() + 1 != cameras.size())
    throw Error("rig: " + std::to_string(cameras.size()) + " cameras need " + std::to_string(cameras.size() - 1) +
                " extrinsics, got " + std::to_string(extrinsics.size()));
  for (std::size_t k = 0; k < cameras.size(); ++k) {
    const Camera& c = cameras[k];
    if (c.width <= 0 || c.height <= 0 || !(c.intrinsics.fx > 0.0) || !(c.intrinsics.fy > 0.0))
      throw Error("rig: camera " + std::to_string(k) + " needs a positive image size and focal length");
  }
  if (!((tolerance.array() > 0.0).all())) throw Error("rig: every extrinsic tolerance must be positive");
}

Rig paperRig(double baseline_m, int width, int height, double horizontalFov_rad) {
  Camera camera;
  camera.width = width;
  camera.height = height;
  const double f = focalLengthFromFov(horizontalFov_rad, width);
  camera.intrinsics = {f, f, 0.5 * width, 0.5 * height};
  Rig rig;
  rig.cameras = {camera, camera};
  rig.extrinsics = {(VertexStereoExtrinsic::Vector6() << baseline_m, 0, 0, 0, 0, 0).finished()};
  rig.validate();
  return rig;
}

}  // namespace lrsvo
