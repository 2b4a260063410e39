#include "lrsvo/eval/run_report.h"

#include <cstdlib>
#include <fstream>

#include "lrsvo/eval/plotting.h"
#include "lrsvo/eval/trajectory_association.h"
#include "lrsvo/eval/trajectory_metrics.h"
#include "lrsvo/eval/trajectory_plots.h"
#include "lrsvo/frontend/datasets/pose_file.h"

namespace lrsvo {
namespace {

nlohmann::json runJson(const RunTotals& t) {
  const double frames = std::max(1, t.frames);
  return {{"frames", t.frames},
          {"frames_tracked", t.tracked},
          {"frames_predicted", t.predicted},
          {"frames_bad", t.badFrames},
          {"frames_realigned", t.frontEnd.realigned},
          {"tracks_revived", t.frontEnd.revived},
          {"frames_relocalised", t.relocalised},
          {"keyframes", t.keyframes},
          {"segments", t.segments},
          {"fps", t.fps()},
          {"odometry_s", t.odometrySeconds()},
          {"source_s", t.sourceSeconds},
          {"ms_per_frame",
           {{"detect", t.frontEnd.detect_ms / frames},
            {"track", t.frontEnd.track_ms / frames},
            {"stereo_match", t.frontEnd.stereo_ms / frames},
            {"undistort", t.frontEnd.undistort_ms / frames},
            {"initialize", t.backEnd.initialize_ms / frames},
            {"pose", t.backEnd.pose_ms / frames},
            {"triangulate", t.backEnd.triangulate_ms / frames},
            {"window_adjustment", t.backEnd.bundle_ms / frames}}}};
}

Trajectory truthTrajectory(const GroundTruth& truth) {
  Trajectory trajectory;
  for (const TimedPose& pose : truth.poses) trajectory.add(pose.time_s, pose.worldFromCamera);
  return trajectory;
}

// eval/plots/extrinsics.py: the six parameters of S over time with their bounds (the paper's Figs. 24-25).
std::string plotExtrinsics(const std::filesystem::path& outDir, std::vector<std::filesystem::path>& plots) {
  const std::string python = plottingPython();
  const std::filesystem::path script = plottingScript("extrinsics");
  if (python.empty() || script.empty()) return "no plotting Python or script: extrinsic plot skipped";
  const std::filesystem::path png = outDir / "extrinsics.png";
  const std::string command = plottingCommand(
      python, script, {(outDir / "extrinsics.csv").string(), (outDir / "rig.json").string(), png.string()});
  if (std::system(command.c_str()) != 0) return "the extrinsic plot failed: " + command;
  plots.push_back(png);
  return {};
}

}  // namespace

RunReport writeRunReport(const std::filesystem::path& outDir, const RunResult& run, const GroundTruth& truth,
                         bool plots) {
  RunReport report;
  report.metrics = runJson(run.totals);
  report.metrics["stopped_early"] = run.stopped;
  if (truth.poses.empty()) {
    report.warning = "the source has no ground truth: no trajectory metrics";
  } else if (run.trajectory.size() < 2) {
    report.warning = "fewer than two tracked frames: no trajectory metrics";
  } else {
    const Trajectory truthPoses = truthTrajectory(truth);
    if (!outDir.empty()) writeTumTrajectory(outDir / "groundtruth.tum", truthPoses);
    const AssociatedTrajectories matched = associateByTime(run.trajectory, truthPoses);
    if (matched.estimate.size() < 2) {
      report.warning = "the estimate's times match no ground truth: no trajectory metrics";
    } else {
      const TrajectoryMetrics metrics = computeTrajectoryMetrics(matched);
      nlohmann::json trajectory = toJson(metrics);
      trajectory["frames_matched"] = trajectory["frames"];
      trajectory.erase("frames");
      report.metrics.update(trajectory);
      if (!outDir.empty()) writeTrajectoryTable(outDir, matched, metrics, true);
      if (plots && !outDir.empty()) {
        const TrajectoryPlots drawn = plotTrajectory(outDir);
        report.plots = drawn.files;
        report.warning = drawn.warning;
      }
    }
  }
  if (plots && !outDir.empty() && run.totals.tracked > 0) {
    const std::string warning = plotExtrinsics(outDir, report.plots);
    if (!warning.empty()) report.warning += (report.warning.empty() ? "" : "; ") + warning;
  }
  if (!outDir.empty()) std::ofstream(outDir / "metrics.json") << report.metrics.dump(2) << '\n';
  return report;
}

}  // namespace lrsvo
