#pragma once

#include <Eigen/Geometry>

#include "lrsvo/edges/pinhole.h"

namespace lrsvo {

// Epipolar geometry of a calibrated pair: the fundamental matrix F with
// x1^T F x0 = 0 for homogeneous pixels x0 (base image) and x1 (secondary
// image) of one world point, given the pair's intrinsics and the rigid
// transform X_c1 = secondaryFromBase * X_c0.
Eigen::Matrix3d fundamentalMatrix(const PinholeIntrinsics& base, const PinholeIntrinsics& secondary,
                                  const Eigen::Isometry3d& secondaryFromBase);

// The epipolar line F x0 in the secondary image of a base pixel, as (a, b, c)
// with a u + b v + c = 0 and a^2 + b^2 = 1. Throws lrsvo::Error when F maps
// the pixel to no line (the pixel is the base image's epipole, or F is zero).
Eigen::Vector3d epipolarLine(const Eigen::Matrix3d& fundamental, const Eigen::Vector2d& basePixel);

// Distance in pixels of a secondary pixel from the epipolar line of a base pixel.
double epipolarDistance(const Eigen::Matrix3d& fundamental, const Eigen::Vector2d& basePixel,
                        const Eigen::Vector2d& secondaryPixel);

}  // namespace lrsvo
