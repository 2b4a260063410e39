#pragma once

namespace lrsvo {

// Depth resolution of a perfect, rectified stereo pair (the paper's Fig. 1):
// focal length f in pixels, baseline b and depth Z in metres.

// Disparity d = f b / Z in pixels.
double disparity_px(double focal_px, double baseline_m, double depth_m);

// The exact depth step of one pixel of disparity: Z(d - 1) - Z(d), the depth
// gained when the disparity drops by one pixel. Infinite when d <= 1.
double depthStepExact_m(double focal_px, double baseline_m, double depth_m);

// The step one pixel further: Z(d) - Z(d + 1), the depth lost when the disparity grows by one pixel.
double depthStepNearer_m(double focal_px, double baseline_m, double depth_m);

// The first-order step |dZ/dd| = Z^2 / (f b).
double depthStepFirstOrder_m(double focal_px, double baseline_m, double depth_m);

}  // namespace lrsvo
