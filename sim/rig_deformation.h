#pragma once

#include <cstdint>
#include <vector>

#include "lrsvo/vertices/vertex_stereo_extrinsic.h"

namespace lrsvo {

// How a secondary camera's true extrinsic s = (x, y, z, roll, pitch, yaw)
// (docs/method.md: c in the base frame, angles of R_s) departs from its calibration
// in flight. Defaults, against the paper's bounds of +-1 mm and +-10 mrad:
// - drift 0.3 mm and 2 mrad (0.11 deg): at f ~ 1670 px a 2 mrad rotation moves
//   the secondary image by ~3 px, the paper's "0.2 deg -> ~3 px" regime in
//   which rigid stereo fails, yet well inside the bounds the estimator uses;
// - vibration 0.05 mm and 0.2 mrad per frame (~0.3 px): frame-to-frame jitter
//   a window's single shared S cannot follow, so kept below the 1 px noise;
// - drift period 20 s: S barely moves over a 12-15 frame window (0.5 s at
//   30 Hz), as the shared-S model assumes, but wanders over a minutes-long flight.
struct DeformationOptions {
  using Vector6 = VertexStereoExtrinsic::Vector6;
  Vector6 drift = (Vector6() << 3e-4, 3e-4, 3e-4, 2e-3, 2e-3, 2e-3).finished();  // amplitude per parameter (m, rad)
  double driftPeriod_s = 20.0;  // typical period of the slow drift (its sinusoids span half to twice this)
  Vector6 vibration = (Vector6() << 5e-5, 5e-5, 5e-5, 2e-4, 2e-4, 2e-4).finished();  // per-frame sigma (m, rad)
  Vector6 offset = Vector6::Zero();  // constant deformation (calibration error) in every frame
  std::uint64_t seed = 1;
};

// The true extrinsic of secondary camera `camera` (>= 1) at each time:
// calibration + offset + drift(t) + vibration. The drift is smooth, a weighted
// sum of three sinusoids per parameter, so |drift| <= its amplitude; the
// vibration is an independent Gaussian draw per time. Each camera draws from
// its own stream (seed mixed with the camera index); the same arguments give
// the same result. Throws lrsvo::Error on negative amplitudes, a non-positive
// period, non-finite input or camera < 1.
std::vector<VertexStereoExtrinsic::Vector6> simulateDeformation(const VertexStereoExtrinsic::Vector6& calibration,
                                                                const std::vector<double>& times_s,
                                                                const DeformationOptions& options, int camera);

}  // namespace lrsvo
