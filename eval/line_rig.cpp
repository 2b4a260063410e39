#include "lrsvo/eval/line_rig.h"

#include <string>

#include "lrsvo/graph/error.h"

namespace lrsvo {

LineRig LineRig::evenlySpaced(const PinholeIntrinsics& intrinsics, int cameras, double spacing_m) {
  if (cameras < 2 || !(spacing_m > 0.0))
    throw Error("line rig: needs at least two cameras and a positive spacing, got " + std::to_string(cameras) +
                " cameras " + std::to_string(spacing_m) + " m apart");
  LineRig rig{intrinsics, {}};
  for (int k = 0; k < cameras; ++k) rig.centres_m.push_back((k - 0.5 * (cameras - 1)) * spacing_m);
  return rig;
}

Eigen::Vector2d LineRig::project(int camera, const Eigen::Vector3d& point) const {
  return intrinsics.project(point - Eigen::Vector3d(centres_m.at(camera), 0.0, 0.0));
}

std::vector<TriangulationView> LineRig::views(std::span<const Eigen::Vector2d> pixels) const {
  if (pixels.size() != centres_m.size())
    throw Error("line rig: " + std::to_string(pixels.size()) + " pixels for " + std::to_string(centres_m.size()) +
                " cameras");
  std::vector<TriangulationView> result;
  for (std::size_t k = 0; k < pixels.size(); ++k) {
    TriangulationView view{Eigen::Isometry3d::Identity(), intrinsics, pixels[k]};
    view.cameraFromWorld.translation() = Eigen::Vector3d(-centres_m[k], 0.0, 0.0);
    result.push_back(view);
  }
  return result;
}

std::optional<Eigen::Vector3d> triangulateOnLine(const LineRig& rig, std::span<const Eigen::Vector2d> pixels) {
  const std::size_t n = rig.centres_m.size();
  if (pixels.size() != n || n < 2)
    throw Error("triangulateOnLine: one pixel per camera and at least two cameras, got " +
                std::to_string(pixels.size()) + " pixels for " + std::to_string(n) + " cameras");
  const PinholeIntrinsics& k = rig.intrinsics;
  double meanX = 0.0, meanU = 0.0, meanV = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    meanX += rig.centres_m[i];
    meanU += (pixels[i].x() - k.cx) / k.fx;
    meanV += (pixels[i].y() - k.cy) / k.fy;
  }
  meanX /= n;
  meanU /= n;
  meanV /= n;
  double sxx = 0.0, sxu = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = rig.centres_m[i] - meanX;
    sxx += dx * dx;
    sxu += dx * ((pixels[i].x() - k.cx) / k.fx - meanU);
  }
  if (!(sxx > 0.0)) throw Error("triangulateOnLine: the camera centres coincide");
  // Normalised u = a - x w with a = X/Z, w = 1/Z: w is minus the slope.
  const double inverseDepth = -sxu / sxx;
  if (!(inverseDepth > 0.0)) return std::nullopt;
  const double a = meanU + meanX * inverseDepth;
  const double depth = 1.0 / inverseDepth;
  return Eigen::Vector3d(a * depth, meanV * depth, depth);
}

}  // namespace lrsvo
