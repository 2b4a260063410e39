#include "lrsvo/eval/deformed_pair.h"

#include <limits>

#include "lrsvo/frontend/features/epipolar.h"
#include "lrsvo/frontend/odometry/triangulation.h"
#include "lrsvo/graph/error.h"

namespace lrsvo {

std::string describe(DeformationKind kind, int axis) {
  static const char* const kAxes[] = {"x", "y", "z"};
  static const char* const kRotationNames[] = {" (pitch)", " (yaw)", " (roll)"};
  if (axis < 0 || axis > 2) throw Error("deformation axis " + std::to_string(axis) + ": expected 0, 1 or 2");
  return kind == DeformationKind::kTranslation ? std::string("translation along ") + kAxes[axis]
                                               : std::string("rotation about ") + kAxes[axis] + kRotationNames[axis];
}

VertexStereoExtrinsic::Vector6 verticalPairCalibration(double baseline_m) {
  return (VertexStereoExtrinsic::Vector6() << 0.0, baseline_m, 0.0, 0.0, 0.0, 0.0).finished();
}

VertexStereoExtrinsic::Vector6 deformedExtrinsic(const VertexStereoExtrinsic::Vector6& calibration,
                                                 const Deformation& deformation) {
  if (deformation.axis < 0 || deformation.axis > 2)
    throw Error("deformation axis " + std::to_string(deformation.axis) + ": expected 0, 1 or 2");
  VertexStereoExtrinsic::Vector6 deformed = calibration;
  const int offset = deformation.kind == DeformationKind::kTranslation ? 0 : 3;
  deformed[offset + deformation.axis] += deformation.amount;
  return deformed;
}

std::vector<Deformation> deformationSweep(double maxTranslation_m, double maxRotation_rad, int stepsPerSide) {
  if (stepsPerSide <= 0) throw Error("deformation sweep: needs at least one step per side");
  std::vector<Deformation> sweep;
  for (DeformationKind kind : {DeformationKind::kTranslation, DeformationKind::kRotation}) {
    const double largest = kind == DeformationKind::kTranslation ? maxTranslation_m : maxRotation_rad;
    for (int axis = 0; axis < 3; ++axis)
      for (int step = -stepsPerSide; step <= stepsPerSide; ++step)
        sweep.push_back({kind, axis, largest * step / stepsPerSide});
  }
  return sweep;
}

DeformedPairErrors deformedPairErrors(const PinholeIntrinsics& intrinsics,
                                      const VertexStereoExtrinsic::Vector6& calibration,
                                      const VertexStereoExtrinsic::Vector6& deformed, const Eigen::Vector3d& point) {
  const Eigen::Isometry3d calibrated = secondaryFromBase(calibration);
  const Eigen::Vector3d inDeformed = secondaryFromBase(deformed) * point;
  if (point.z() <= 0.0 || inDeformed.z() <= 0.0)
    throw Error("deformed pair: the point must lie in front of both cameras");
  const Eigen::Vector2d basePixel = intrinsics.project(point);
  const Eigen::Vector2d secondaryPixel = intrinsics.project(inDeformed);

  DeformedPairErrors errors;
  errors.epipolar_px =
      epipolarDistance(fundamentalMatrix(intrinsics, intrinsics, calibrated), basePixel, secondaryPixel);

  TriangulationView base{Eigen::Isometry3d::Identity(), intrinsics, basePixel};
  TriangulationView secondary{calibrated, intrinsics, secondaryPixel};
  const TriangulationResult result = triangulate({base, secondary});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  errors.triangulation_m = result.valid ? (result.point - point).norm() : nan;
  errors.triangulatedDepth_m = result.valid ? result.point.z() : nan;
  return errors;
}

}  // namespace lrsvo
