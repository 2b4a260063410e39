#include "lrsvo/eval/paper_cameras.h"

#include "lrsvo/frontend/odometry/rig.h"

namespace lrsvo {

double paperOpticsFocal_px() { return focalLengthPixels(kPaperLens_mm, kPaperSensorWidth_mm, kPaperImageWidth); }

PinholeIntrinsics paperIntrinsics(double focal_px) {
  return {focal_px, focal_px, 0.5 * kPaperImageWidth, 0.5 * kPaperImageHeight};
}

}  // namespace lrsvo
