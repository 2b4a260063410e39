#include "lrsvo/sim/footprint.h"

#include <cmath>
#include <string>

#include "lrsvo/graph/error.h"

namespace lrsvo {

std::array<Eigen::Vector2d, 4> groundFootprint(const Camera& camera, const Eigen::Isometry3d& cameraFromWorld,
                                               double planeZ) {
  const Eigen::Isometry3d worldFromCamera = cameraFromWorld.inverse();
  const Eigen::Vector3d centre = worldFromCamera.translation();
  const PinholeIntrinsics& k = camera.intrinsics;
  const std::array<Eigen::Vector2d, 4> pixels = {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(camera.width, 0.0),
                                                 Eigen::Vector2d(camera.width, camera.height),
                                                 Eigen::Vector2d(0.0, camera.height)};
  std::array<Eigen::Vector2d, 4> corners;
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d ray =
        worldFromCamera.linear() * Eigen::Vector3d((pixels[i].x() - k.cx) / k.fx, (pixels[i].y() - k.cy) / k.fy, 1.0);
    const double distance = (planeZ - centre.z()) / ray.z();
    if (!(ray.z() < 0.0 && distance > 0.0 && std::isfinite(distance)))
      throw Error("ground footprint: the ray through image corner " + std::to_string(i) +
                  " does not reach the plane z = " + std::to_string(planeZ) + " m from a camera at z = " +
                  std::to_string(centre.z()) + " m; the camera must be above the plane and look down");
    corners[i] = (centre + distance * ray).head<2>();
  }
  return corners;
}

double polygonArea(const std::array<Eigen::Vector2d, 4>& corners) {
  double twiceArea = 0.0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Eigen::Vector2d& a = corners[i];
    const Eigen::Vector2d& b = corners[(i + 1) % corners.size()];
    twiceArea += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * std::abs(twiceArea);
}

}  // namespace lrsvo
