#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "lrsvo/eval/trajectory_metrics.h"

namespace lrsvo {

// Writes outDir/trajectory.csv: per matched pose its time (column time_s, or
// frame when `timesKnown` is false, e.g. KITTI poses without a times file), the
// true position, the SE3-aligned estimated position, and the position (m) and
// orientation (deg) errors after that alignment. Returns the file's path.
std::filesystem::path writeTrajectoryTable(const std::filesystem::path& outDir, const AssociatedTrajectories& matched,
                                           const TrajectoryMetrics& metrics, bool timesKnown);

// What plotting produced: the PNGs written, or why there are none.
struct TrajectoryPlots {
  std::vector<std::filesystem::path> files;
  std::string warning;  // empty when the plots were drawn
};

// Runs eval/plots/trajectory.py on outDir/trajectory.csv: trajectory_top.png
// (top-down, estimate against truth), position_error.png and
// orientation_error.png. Never throws for a missing Python or a failed plot:
// it says so in `warning`.
TrajectoryPlots plotTrajectory(const std::filesystem::path& outDir);

}  // namespace lrsvo
