#pragma once

#include <array>

#include <Eigen/Geometry>

#include "lrsvo/frontend/odometry/rig.h"

namespace lrsvo {

// Where the rays through the four image corners of `camera` (at pose
// camera-from-world) meet the horizontal plane z = planeZ, in world x, y:
// the camera's ground footprint on that plane, a convex quadrilateral.
// Throws lrsvo::Error when a corner ray does not reach the plane (the camera
// is below it or sees the horizon).
std::array<Eigen::Vector2d, 4> groundFootprint(const Camera& camera, const Eigen::Isometry3d& cameraFromWorld,
                                               double planeZ);

// Area of a simple polygon given by its corners in order (shoelace formula).
double polygonArea(const std::array<Eigen::Vector2d, 4>& corners);

}  // namespace lrsvo
