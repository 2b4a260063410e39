#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "lrsvo/edges/pinhole.h"
#include "lrsvo/vertices/vertex_stereo_extrinsic.h"

namespace lrsvo {

// The set-up of the paper's Section 2 (Figs. 4 and 5): a stereo pair whose
// secondary camera is moved away from its calibration, and a point seen by both.
//
// Camera frames: x to the right in the image, y down the image, z along the
// optical axis. In the vertically aligned pair the secondary centre sits the
// baseline along the base camera's +y (the image's vertical axis), with no
// rotation, so the epipolar lines are the image's columns. The paper names
// rotations the usual camera way: pitch about x, yaw about y, roll about z.
// (VertexStereoExtrinsic's parameters are named by frame order instead: its
// "roll, pitch, yaw" are the angles about x, y, z.)
enum class DeformationKind { kTranslation, kRotation };

struct Deformation {
  DeformationKind kind = DeformationKind::kTranslation;
  int axis = 0;         // 0, 1, 2: about / along the base camera's x, y, z
  double amount = 0.0;  // metres added to the secondary centre, or radians added to its angle about the axis
};

// "translation along y", "rotation about x (pitch)", ...
std::string describe(DeformationKind kind, int axis);

// The vertically aligned pair's calibration: c = (0, baseline, 0), no rotation.
VertexStereoExtrinsic::Vector6 verticalPairCalibration(double baseline_m);

// The calibration with one parameter changed by the deformation.
VertexStereoExtrinsic::Vector6 deformedExtrinsic(const VertexStereoExtrinsic::Vector6& calibration,
                                                 const Deformation& deformation);

// The sweep of Figs. 4 and 5, both signs: for each axis, translations from
// -maxTranslation to +maxTranslation and rotations from -maxRotation to
// +maxRotation, in 2 * stepsPerSide + 1 equal steps (zero included).
std::vector<Deformation> deformationSweep(double maxTranslation_m, double maxRotation_rad, int stepsPerSide);

struct DeformedPairErrors {
  // Distance of the point's projection in the deformed secondary camera from
  // the epipolar line that the calibration gives for its base projection.
  double epipolar_px = 0.0;
  // Distance from the true point of the point triangulated from both
  // projections with the calibration (least squares, frontend's triangulate).
  // NaN when no point in front of both cameras fits (negative disparity).
  double triangulation_m = 0.0;
  double triangulatedDepth_m = 0.0;  // NaN likewise
};

// Both cameras share `intrinsics`; `point` is in the base camera's frame.
DeformedPairErrors deformedPairErrors(const PinholeIntrinsics& intrinsics,
                                      const VertexStereoExtrinsic::Vector6& calibration,
                                      const VertexStereoExtrinsic::Vector6& deformed, const Eigen::Vector3d& point);

}  // namespace lrsvo
