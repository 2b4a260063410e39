#pragma once

#include <string>

#include "lrsvo/frontend/datasets/frame_source.h"
#include "lrsvo/frontend/odometry/rig.h"

namespace lrsvo {

struct FrameCheckOptions {
  // An image whose grey levels spread less than this (standard deviation)
  // holds nothing to track: a dropped frame sent as a uniform one, a lens
  // cap, a saturated sensor. A textured scene, even dim, spreads by several
  // levels, and sensor noise alone by about one.
  double minGreyStd = 1.0;
};

// What is wrong with an image's shape for a camera, or "" when nothing: empty,
// not 8-bit grey, or sized otherwise than the camera's calibration.
std::string imageShapeDefect(const cv::Mat& image, const Camera& camera);

// Why a frame's images cannot be used, or "" when they can: the source's own
// verdict (StereoFrame::defect: a missing or undecodable file), a camera
// count other than the rig's, or an image held in the frame that is empty,
// not 8-bit grey, sized otherwise than its camera's calibration, or blank.
// Deferred images are not made here (they are checked when made).
std::string frameDefect(const StereoFrame& frame, const Rig& rig, const FrameCheckOptions& options = {});

}  // namespace lrsvo
