#pragma once

#include <cstdint>
#include <string>

#include "lrsvo/graph/graph.h"

namespace lrsvo {

// Shapes of generated pose graphs.
enum class PoseGraphShape {
  // Poses on rings of a sphere, travelling along each ring and on to the
  // next; every pose past the first ring also sees the pose beside it on the
  // ring before (a loop closure). SE3 poses.
  kSphere,
  // A walk on a square (2D, SE2 poses) or cubic (3D, SE3 poses) lattice, one
  // unit step along an axis at a time, inside a box of about N / 4 cells so
  // that it comes back often; each return to a visited cell closes a loop
  // with the latest earlier pose there.
  kGrid,
};

// Parses "sphere" or "grid"; throws lrsvo::Error otherwise.
PoseGraphShape poseGraphShapeFromName(const std::string& name);

struct PoseGraphOptions {
  PoseGraphShape shape = PoseGraphShape::kSphere;
  int dimension = 3;  // the grid's: 2 (SE2) or 3 (SE3); a sphere is 3
  int poses = 2500;
  std::uint64_t seed = 1;
  double radius = 10.0;  // the sphere's, in the unit of the grid's step
  // Sigmas of the measurement noise: on each translation axis, and on each
  // rotation angle (SE2's heading; SE3's rotation vector, applied on the right).
  double translationSigma = 0.05;
  double rotationSigma = 0.01;
};

// A seeded pose graph: the true poses measured by odometry edges along the
// path and by loop closures, each relative pose with independent Gaussian
// noise, and information the inverse covariance of that noise (for SE3 the
// rotation residual is a quaternion's vector part, half the angle: 4 / sigma^2).
// The estimates start at the first true pose chained by the noisy odometry.
// No vertex is fixed. The same options give the same graph on every platform.
// Throws lrsvo::Error on fewer than 2 poses, a dimension other than 2 or 3,
// a 2D sphere, or non-positive sigmas.
Graph generatePoseGraph(const PoseGraphOptions& options);

}  // namespace lrsvo
