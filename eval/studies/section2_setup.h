#pragma once

// The set-up of the paper's Section 2, shared by Figs. 4 and 5: a vertically
// aligned pair 0.7 m apart, a point 100 m along the base camera's optical
// axis, the second camera translated up to 0.1 m or rotated up to 0.5 deg.

#include "lrsvo/eval/deformed_pair.h"
#include "lrsvo/eval/paper_cameras.h"

namespace lrsvo::section2 {

inline constexpr double kBaseline_m = 0.7, kDepth_m = 100.0;
inline constexpr double kMaxTranslation_m = 0.1, kMaxRotation_deg = 0.5;
inline constexpr int kStepsPerSide = 50;
inline constexpr double kCheckRotation_deg = 0.2, kCheckTranslation_m = 0.05;

// The epipolar and triangulation errors of the point for one deformation.
inline DeformedPairErrors errorsOf(double focal_px, const Deformation& deformation) {
  const VertexStereoExtrinsic::Vector6 calibration = verticalPairCalibration(kBaseline_m);
  return deformedPairErrors(paperIntrinsics(focal_px), calibration, deformedExtrinsic(calibration, deformation),
                            Eigen::Vector3d(0.0, 0.0, kDepth_m));
}

}  // namespace lrsvo::section2
