#pragma once

#include "lrsvo/edges/pinhole.h"

namespace lrsvo {

// The cameras of the paper's simulations (Sections 2 and 3): a 6 mm lens on a
// 1/3" sensor (4.8 mm x 3.6 mm) at 1024 x 768 pixels.
inline constexpr double kPaperLens_mm = 6.0;
inline constexpr double kPaperSensorWidth_mm = 4.8;
inline constexpr int kPaperImageWidth = 1024;
inline constexpr int kPaperImageHeight = 768;

// Fig. 1's normalised focal length.
inline constexpr double kFigure1Focal_px = 1200.0;
// The focal length the text implies: "0.2 deg -> ~3 px" needs f = 3 px / 0.2 deg
// = 859 px, rounded (docs/method.md, note on implicit settings).
inline constexpr double kImpliedFocal_px = 860.0;

// f = lens / pixel pitch = 6 mm * 1024 px / 4.8 mm = 1280 px.
double paperOpticsFocal_px();

// Square pixels of the given focal length, principal point at the centre of the 1024 x 768 image.
PinholeIntrinsics paperIntrinsics(double focal_px);

}  // namespace lrsvo
