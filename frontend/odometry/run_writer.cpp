#include "lrsvo/frontend/odometry/run_writer.h"

#include <iomanip>
#include <sstream>
#include <string>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

std::ofstream openOutput(const std::filesystem::path& file) {
  std::ofstream out(file);
  if (!out) throw Error("cannot write " + file.string());
  out << std::setprecision(15);
  return out;
}

std::ostringstream lineBuffer() {
  std::ostringstream buffer;
  buffer << std::setprecision(15);
  return buffer;
}

// Lines shorter than the stream's buffer leave it in one write(2) at the flush.
void writeWhole(std::ofstream& out, const std::string& lines) {
  out << lines;
  out.flush();
}

// A free-text CSV field: commas and line breaks would split the row.
std::string csvField(std::string text) {
  for (char& c : text)
    if (c == ',' || c == '\n' || c == '\r') c = ';';
  return text;
}

nlohmann::json vectorJson(const VertexStereoExtrinsic::Vector6& v) {
  return std::vector<double>(v.data(), v.data() + 6);
}

}  // namespace

RunWriter::RunWriter(const std::filesystem::path& outDir, const Rig& rig, GroundTruth truth, int firstFrame)
    : rig_(rig), truth_(std::move(truth)), firstFrame_(firstFrame) {
  std::error_code error;
  std::filesystem::create_directories(outDir, error);
  if (error) throw Error("cannot create the output folder " + outDir.string() + ": " + error.message());
  trajectory_ = openOutput(outDir / "trajectory.tum");
  trajectory_ << "# lrsvo: base camera, world-from-camera; t tx ty tz qx qy qz qw (a pose ending '# predicted' is "
                 "the constant-velocity prediction through a tracking loss, not measured)\n";
  extrinsics_ = openOutput(outDir / "extrinsics.csv");
  extrinsics_ << "frame,time_s,camera,x_m,y_m,z_m,roll_rad,pitch_rad,yaw_rad,true_x_m,true_y_m,true_z_m,true_roll_rad,"
                 "true_pitch_rad,true_yaw_rad\n";
  frames_ = openOutput(outDir / "frames.csv");
  frames_ << "frame,time_s,tracked,keyframe,segment,features,tracked_features,new_features,stereo_matches,"
             "mapped_matches,pose_inliers,map_points,window_frames,window_rms_px,outlier_threshold_px,"
             "bundle_iterations,detect_ms,track_ms,stereo_ms,undistort_ms,initialize_ms,pose_ms,triangulate_ms,"
             "bundle_ms,realigned,revived,status,note\n";

  nlohmann::json rigJson;
  for (int k = 1; k <= rig.secondaryCount(); ++k)
    rigJson["secondary"].push_back({{"camera", k}, {"calibration", vectorJson(rig.extrinsics[k - 1])}});
  rigJson["tolerance"] = vectorJson(rig.tolerance);
  rigJson["parameters"] = {"x_m", "y_m", "z_m", "roll_rad", "pitch_rad", "yaw_rad"};
  openOutput(outDir / "rig.json") << rigJson.dump(2) << '\n';
}

void RunWriter::write(const FrameEstimate& e, const FrontEndTimings& f) {
  // Each file gets a frame's lines in one flushed write: a run killed at any
  // moment leaves whole lines (at most the last frame's missing), never half of one.
  const std::size_t frame = static_cast<std::size_t>(firstFrame_ + e.frame);
  std::ostringstream frames = lineBuffer();
  frames << frame << ',' << e.time_s << ',' << e.tracked << ',' << e.keyframe << ',' << e.segment << ','
         << e.observations << ',' << f.tracked << ',' << f.added << ',' << f.stereoMatched << ',' << e.mappedMatches
         << ',' << e.poseInliers << ',' << e.mapPoints << ',' << e.windowFrames << ',' << e.windowRmsError_px << ','
         << e.outlierThreshold_px << ',' << e.bundleIterations << ',' << f.detect_ms << ',' << f.track_ms << ','
         << f.stereo_ms << ',' << f.undistort_ms << ',' << e.times.initialize_ms << ',' << e.times.pose_ms << ','
         << e.times.triangulate_ms << ',' << e.times.bundle_ms << ',' << f.realigned << ',' << f.revived << ','
         << frameStatusName(e) << ',' << csvField(e.note) << '\n';
  writeWhole(frames_, frames.str());
  if (!e.tracked && !e.predicted) return;
  const Eigen::Isometry3d worldFromCamera = e.cameraFromWorld.inverse();
  const Eigen::Quaterniond q(worldFromCamera.rotation());
  const Eigen::Vector3d& t = worldFromCamera.translation();
  std::ostringstream pose = lineBuffer();
  pose << e.time_s << ' ' << t.x() << ' ' << t.y() << ' ' << t.z() << ' ' << q.x() << ' ' << q.y() << ' ' << q.z()
       << ' ' << q.w() << (e.predicted ? " # predicted\n" : "\n");
  writeWhole(trajectory_, pose.str());
  if (!e.tracked) return;
  std::ostringstream extrinsics = lineBuffer();
  for (std::size_t k = 0; k < e.extrinsics.size(); ++k) {
    extrinsics << frame << ',' << e.time_s << ',' << k + 1;
    for (int i = 0; i < 6; ++i) extrinsics << ',' << e.extrinsics[k][i];
    const bool truthKnown = frame < truth_.extrinsics.size() && k < truth_.extrinsics[frame].size();
    for (int i = 0; i < 6; ++i) {
      extrinsics << ',';
      if (truthKnown) extrinsics << truth_.extrinsics[frame][k][i];
    }
    extrinsics << '\n';
  }
  writeWhole(extrinsics_, extrinsics.str());
}

}  // namespace lrsvo
