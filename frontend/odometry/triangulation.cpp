#include "lrsvo/frontend/odometry/triangulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Cholesky>
#include <Eigen/SVD>

#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

Eigen::Vector2d normalised(const TriangulationView& view) {
  const PinholeIntrinsics& k = view.intrinsics;
  return {(view.pixel.x() - k.cx) / k.fx, (view.pixel.y() - k.cy) / k.fy};
}

double largestRayAngle(const std::vector<TriangulationView>& views, const Eigen::Vector3d& point) {
  double largest = 0.0;
  for (std::size_t a = 0; a < views.size(); ++a) {
    const Eigen::Vector3d rayA = point - views[a].cameraFromWorld.inverse().translation();
    for (std::size_t b = a + 1; b < views.size(); ++b) {
      const Eigen::Vector3d rayB = point - views[b].cameraFromWorld.inverse().translation();
      largest = std::max(largest, std::atan2(rayA.cross(rayB).norm(), rayA.dot(rayB)));
    }
  }
  return largest;
}

}  // namespace

Eigen::Vector3d triangulateLinear(const std::vector<TriangulationView>& views) {
  if (views.size() < 2)
    throw Error("triangulate: a point needs at least two views, got " + std::to_string(views.size()));
  Eigen::MatrixXd a(2 * views.size(), 4);
  for (std::size_t i = 0; i < views.size(); ++i) {
    const Eigen::Matrix<double, 3, 4> p = views[i].cameraFromWorld.matrix().topRows<3>();
    const Eigen::Vector2d x = normalised(views[i]);
    // Each row normalised so that distant and near cameras weigh alike.
    Eigen::RowVector4d rowX = x.x() * p.row(2) - p.row(0);
    Eigen::RowVector4d rowY = x.y() * p.row(2) - p.row(1);
    a.row(2 * i) = rowX / rowX.norm();
    a.row(2 * i + 1) = rowY / rowY.norm();
  }
  const Eigen::Vector4d h = Eigen::JacobiSVD<Eigen::MatrixXd>(a, Eigen::ComputeFullV).matrixV().col(3);
  return h.head<3>() / h[3];
}

TriangulationResult triangulate(const std::vector<TriangulationView>& views, const TriangulationOptions& options) {
  TriangulationResult result;
  result.point = triangulateLinear(views);
  if (!result.point.allFinite()) return result;

  auto sumSquaredError = [&](const Eigen::Vector3d& point, Eigen::Matrix3d* h, Eigen::Vector3d* g) {
    double sum = 0.0;
    if (h) h->setZero();
    if (g) g->setZero();
    for (const TriangulationView& view : views) {
      const Eigen::Vector3d inCamera = view.cameraFromWorld * point;
      if (inCamera.z() <= 0.0) return std::numeric_limits<double>::infinity();
      const Eigen::Vector2d r = view.intrinsics.project(inCamera) - view.pixel;
      sum += r.squaredNorm();
      if (h) {
        const Eigen::Matrix<double, 2, 3> j = view.intrinsics.projectJacobian(inCamera) * view.cameraFromWorld.linear();
        *h += j.transpose() * j;
        *g += j.transpose() * r;
      }
    }
    return sum;
  };

  double error = sumSquaredError(result.point, nullptr, nullptr);
  for (int iteration = 0; iteration < options.maxIterations && std::isfinite(error); ++iteration) {
    Eigen::Matrix3d h;
    Eigen::Vector3d g;
    sumSquaredError(result.point, &h, &g);
    const Eigen::Vector3d step = h.ldlt().solve(-g);
    if (!step.allFinite()) break;
    // Step halving keeps the refinement monotone on the nearly degenerate
    // long-range geometry, where the depth direction is poorly conditioned.
    double scale = 1.0;
    double trialError = sumSquaredError(result.point + step, nullptr, nullptr);
    while (!(trialError < error) && scale > 1e-3) {
      scale *= 0.5;
      trialError = sumSquaredError(result.point + scale * step, nullptr, nullptr);
    }
    if (!(trialError < error)) break;
    result.point += scale * step;
    const bool converged = error - trialError < 1e-12 * (1.0 + error);
    error = trialError;
    if (converged) break;
  }

  result.rmsReprojectionError_px = std::sqrt(error / (2.0 * views.size()));
  result.parallax_rad = largestRayAngle(views, result.point);
  result.valid =
      std::isfinite(error) && result.parallax_rad >= options.minParallax_rad &&
      (options.maxReprojectionError_px <= 0.0 || result.rmsReprojectionError_px <= options.maxReprojectionError_px);
  return result;
}

}  // namespace lrsvo
