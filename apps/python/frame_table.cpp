#include "frame_table.h"

#include <limits>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <Eigen/Geometry>

namespace py = pybind11;

namespace lrsvo::python {
namespace {

template <typename T, typename Get>
py::array_t<T> column(const std::vector<FrameEstimate>& estimates, Get get) {
  py::array_t<T> values(static_cast<py::ssize_t>(estimates.size()));
  T* out = values.mutable_data();
  for (const FrameEstimate& estimate : estimates) *out++ = static_cast<T>(get(estimate));
  return values;
}

}  // namespace

py::dict frameTable(const std::vector<FrameEstimate>& estimates, int secondaryCameras) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const auto rows = static_cast<py::ssize_t>(estimates.size());
  py::array_t<double> pose({rows, py::ssize_t{8}});
  py::array_t<double> extrinsics({rows, py::ssize_t{6} * secondaryCameras});
  auto poseRows = pose.mutable_unchecked<2>();
  auto extrinsicRows = extrinsics.mutable_unchecked<2>();
  std::vector<std::string> status, note;
  for (py::ssize_t i = 0; i < rows; ++i) {
    const FrameEstimate& e = estimates[i];
    status.emplace_back(frameStatusName(e));
    note.push_back(e.note);
    const bool posed = e.tracked || e.predicted;
    const Eigen::Isometry3d worldFromCamera = e.cameraFromWorld.inverse();
    const Eigen::Quaterniond q(worldFromCamera.linear());
    const double values[8] = {e.time_s,
                              worldFromCamera.translation().x(),
                              worldFromCamera.translation().y(),
                              worldFromCamera.translation().z(),
                              q.x(),
                              q.y(),
                              q.z(),
                              q.w()};
    for (int c = 0; c < 8; ++c) poseRows(i, c) = posed ? values[c] : (c == 0 ? e.time_s : kNaN);
    for (int k = 0; k < secondaryCameras; ++k)
      for (int c = 0; c < 6; ++c)
        extrinsicRows(i, 6 * k + c) =
            e.tracked && k < static_cast<int>(e.extrinsics.size()) ? e.extrinsics[k][c] : kNaN;
  }
  py::dict table;
  table["frame"] = column<int>(estimates, [](const FrameEstimate& e) { return e.frame; });
  table["time_s"] = column<double>(estimates, [](const FrameEstimate& e) { return e.time_s; });
  table["status"] = status;
  table["note"] = note;
  table["segment"] = column<int>(estimates, [](const FrameEstimate& e) { return e.tracked ? e.segment : -1; });
  table["keyframe"] = column<bool>(estimates, [](const FrameEstimate& e) { return e.keyframe; });
  table["relocalised"] = column<bool>(estimates, [](const FrameEstimate& e) { return e.relocalised; });
  table["observations"] = column<int>(estimates, [](const FrameEstimate& e) { return e.observations; });
  table["mapped_matches"] = column<int>(estimates, [](const FrameEstimate& e) { return e.mappedMatches; });
  table["pose_inliers"] = column<int>(estimates, [](const FrameEstimate& e) { return e.poseInliers; });
  table["map_points"] = column<int>(estimates, [](const FrameEstimate& e) { return e.mapPoints; });
  table["window_frames"] = column<int>(estimates, [](const FrameEstimate& e) { return e.windowFrames; });
  table["window_rms_px"] = column<double>(estimates, [](const FrameEstimate& e) { return e.windowRmsError_px; });
  table["outlier_threshold_px"] =
      column<double>(estimates, [](const FrameEstimate& e) { return e.outlierThreshold_px; });
  table["bundle_iterations"] = column<int>(estimates, [](const FrameEstimate& e) { return e.bundleIterations; });
  table["pose"] = pose;
  table["extrinsics"] = extrinsics;
  return table;
}

}  // namespace lrsvo::python
