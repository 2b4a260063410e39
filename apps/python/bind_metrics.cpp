// lrsvo.trajectory_metrics and the pose files: the numbers of `lrsvo eval` on
// numpy trajectories.
#include <optional>
#include <string>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "lrsvo/eval/trajectory_association.h"
#include "lrsvo/eval/trajectory_metrics.h"
#include "lrsvo/frontend/datasets/pose_file.h"
#include "lrsvo/graph/error.h"
#include "trajectory_arrays.h"

namespace py = pybind11;

namespace lrsvo::python {
namespace {

py::dict trajectoryMetrics(const Eigen::Ref<const Eigen::MatrixXd>& estimateArray,
                           const Eigen::Ref<const Eigen::MatrixXd>& truthArray, const std::string& association,
                           double maxTimeDifference, int rpeDelta, double rpeDelta_m, bool rpeAllPairs,
                           const std::string& rpePath, const std::optional<std::vector<double>>& segmentLengths) {
  const Trajectory estimate = fromArray(estimateArray, "estimate");
  const Trajectory truth = fromArray(truthArray, "truth");
  if (association != "time" && association != "index")
    throw Error("association must be 'time' or 'index', got '" + association + "'");
  if (rpePath != "estimate" && rpePath != "truth")
    throw Error("rpe_path must be 'estimate' or 'truth', got '" + rpePath + "'");
  const AssociatedTrajectories matched =
      association == "index" ? associateByIndex(estimate, truth) : associateByTime(estimate, truth, maxTimeDifference);
  if (matched.estimate.size() < 2)
    throw Error("only " + std::to_string(matched.estimate.size()) + " of " + std::to_string(estimate.size()) +
                " estimated poses match a true one; expected at least 2 (check the times or max_time_difference)");
  TrajectoryMetricsOptions options;
  options.rpeDeltaFrames = rpeDelta;
  options.rpeDelta_m = rpeDelta_m;
  options.rpeAllPairs = rpeAllPairs;
  options.rpePath = rpePath == "truth" ? RpePath::kTruth : RpePath::kEstimate;
  if (segmentLengths) options.driftLengths_m = *segmentLengths;
  const nlohmann::json json = toJson(computeTrajectoryMetrics(matched, options));
  return py::module_::import("json").attr("loads")(json.dump());
}

TrajectoryArray readTrajectory(const std::string& path, const std::string& format, const std::string& times) {
  const PoseFileFormat chosen = format == "auto" ? detectPoseFileFormat(path) : poseFileFormatFromName(format);
  return toArray(chosen == PoseFileFormat::kTum ? readTumTrajectory(path) : readKittiTrajectory(path, times));
}

}  // namespace

void bindMetrics(py::module_& m) {
  m.def("trajectory_metrics", &trajectoryMetrics, py::arg("estimate"), py::arg("truth"),
        py::arg("association") = "time", py::arg("max_time_difference") = 0.02, py::arg("rpe_delta") = 1,
        py::arg("rpe_delta_m") = 100.0, py::arg("rpe_all_pairs") = false, py::arg("rpe_path") = "estimate",
        py::arg("segment_lengths") = std::nullopt,
        "`lrsvo eval`'s metrics of an estimate against the truth, both N x 8 arrays (t, x, y, z, qx, qy, qz, "
        "qw; world-from-camera), as a dict with metrics.json's keys: ate_rmse_m (SE3-aligned), "
        "ate_sim3_rmse_m, rpe_*, drift_percent (KITTI segments), scale_error_percent, "
        "path_length_error_percent, final_position_error_m, ... Poses are matched by time (as TUM's "
        "associate.py) or by index.");
  m.def("read_trajectory", &readTrajectory, py::arg("path"), py::arg("format") = "auto", py::arg("times") = "",
        "Reads a TUM or KITTI pose file as an N x 8 array (KITTI rows get their times from `times`, else 0, 1, ...).");
  m.def(
      "write_trajectory",
      [](const std::string& path, const Eigen::Ref<const Eigen::MatrixXd>& array) {
        writeTumTrajectory(path, fromArray(array, path.c_str()));
      },
      py::arg("path"), py::arg("trajectory"), "Writes an N x 8 trajectory as a TUM pose file.");
}

}  // namespace lrsvo::python
