#pragma once

#include <string>
#include <vector>

#include "frontend/frame_source.h"

namespace lrsvo {

// Reads a trajectory in TUM format, one pose a line: "t tx ty tz qx qy qz qw"
// (world-from-frame); '#' starts a comment. Throws lrsvo::ParseError on a bad line.
std::vector<TimedPose> readTumTrajectory(const std::string& path);

}  // namespace lrsvo
