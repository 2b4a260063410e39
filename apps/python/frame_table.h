#pragma once

#include <vector>

#include <pybind11/pybind11.h>

#include "lrsvo/frontend/odometry/frame_estimate.h"

namespace lrsvo::python {

// Per-frame estimates as a dict of numpy columns, one row per frame, as
// frames.csv holds them: frame, time_s, status ('tracked', 'predicted',
// 'bad_frame', 'initialising'), note, segment (-1 without a pose), keyframe,
// relocalised, the counts and the window's error; pose (N x 8: t, x, y, z, qx,
// qy, qz, qw, world-from-camera; NaN without a pose) and extrinsics
// (N x 6 per secondary camera, the window's S; NaN when not tracked).
pybind11::dict frameTable(const std::vector<FrameEstimate>& estimates, int secondaryCameras);

}  // namespace lrsvo::python
