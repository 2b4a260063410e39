#include "lrsvo/eval/trajectory_plots.h"

#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <limits>
#include <numbers>

#include "lrsvo/eval/plotting.h"
#include "lrsvo/graph/error.h"

namespace lrsvo {

std::filesystem::path writeTrajectoryTable(const std::filesystem::path& outDir, const AssociatedTrajectories& matched,
                                           const TrajectoryMetrics& metrics, bool timesKnown) {
  const Trajectory aligned = transformed(matched.estimate, metrics.se3);
  const std::vector<double> positionError = positionErrors(aligned, matched.truth);
  const std::vector<double> orientationError = orientationErrors(aligned, matched.truth);
  std::filesystem::create_directories(outDir);
  const std::filesystem::path file = outDir / "trajectory.csv";
  std::ofstream out(file);
  if (!out) throw Error("cannot write " + file.string());
  out << std::setprecision(std::numeric_limits<double>::max_digits10);
  out << (timesKnown ? "time_s" : "frame")
      << ",truth_x,truth_y,truth_z,estimate_x,estimate_y,estimate_z,position_error_m,orientation_error_deg\n";
  for (std::size_t i = 0; i < aligned.size(); ++i) {
    const Eigen::Vector3d q = matched.truth.worldFromCamera[i].translation();
    const Eigen::Vector3d p = aligned.worldFromCamera[i].translation();
    out << matched.truth.times_s[i] << ',' << q.x() << ',' << q.y() << ',' << q.z() << ',' << p.x() << ',' << p.y()
        << ',' << p.z() << ',' << positionError[i] << ',' << orientationError[i] * 180.0 / std::numbers::pi << '\n';
  }
  if (!out) throw Error("error writing " + file.string());
  return file;
}

TrajectoryPlots plotTrajectory(const std::filesystem::path& outDir) {
  TrajectoryPlots plots;
  const std::filesystem::path script = plottingScript("trajectory");
  if (script.empty()) {
    plots.warning = "no plotting script eval/plots/trajectory.py found (set LRSVO_PLOTS_DIR)";
    return plots;
  }
  const std::string python = plottingPython();
  if (python.empty()) {
    plots.warning = "plots skipped: no Python with matplotlib (install python3-matplotlib or set LRSVO_PYTHON)";
    return plots;
  }
  const std::string command = plottingCommand(python, script, {outDir.string()});
  if (std::system(command.c_str()) != 0) {
    plots.warning = "the plot script failed: " + command;
    return plots;
  }
  for (const char* name : {"trajectory_top.png", "position_error.png", "orientation_error.png"})
    plots.files.push_back(outDir / name);
  return plots;
}

}  // namespace lrsvo
