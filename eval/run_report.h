#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lrsvo/frontend/datasets/frame_source.h"
#include "lrsvo/frontend/odometry/odometry_run.h"

namespace lrsvo {

// What a finished run reports: its counts and speed, and, when the source
// knows the truth, the trajectory metrics (eval/trajectory_metrics.h).
struct RunReport {
  nlohmann::json metrics;                    // also written as metrics.json
  std::vector<std::filesystem::path> plots;  // PNGs written
  std::string warning;                       // why plots or metrics are missing, if they are
};

// Writes metrics.json (frames, frames_tracked, frames_predicted, frames_bad,
// frames_realigned (tracks predicted by the whole image's shift),
// tracks_revived (found again after a break), frames_relocalised, segments,
// stopped_early (RunOptions::stop ended the run), fps, time per stage,
// and with the truth distance_m, ate_rmse_m, drift_percent,
// scale_error_percent, ...) and the plots (trajectory against truth, position
// and orientation error over time, the extrinsic's six parameters over time
// with their bounds) into outDir; an empty outDir writes nothing.
RunReport writeRunReport(const std::filesystem::path& outDir, const RunResult& run, const GroundTruth& truth,
                         bool plots);

}  // namespace lrsvo
