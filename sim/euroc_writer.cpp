#include "lrsvo/sim/euroc_writer.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include <opencv2/imgcodecs.hpp>

#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

std::ofstream openFile(const std::string& path) {
  std::ofstream out(path);
  if (!out) throw Error("EuRoC writer: cannot write " + path);
  return out;
}

std::string cameraDirectory(const std::string& directory, int camera) {
  return directory + "/mav0/cam" + std::to_string(camera);
}

void writeSensorYaml(const std::string& path, int index, const Camera& camera, const Eigen::Isometry3d& bodyFromCamera,
                     double rate_hz) {
  std::ofstream out = openFile(path);
  const Eigen::Matrix4d t = bodyFromCamera.matrix().array() + 0.0;  // + 0.0: no "-0" in the file
  char line[512];
  out << "%YAML:1.0\n# General sensor definitions.\nsensor_type: camera\ncomment: lrsvo synthetic camera " << index
      << "\n\n# Sensor extrinsics wrt. the body-frame (body = cam0).\nT_BS:\n  cols: 4\n  rows: 4\n  data: [";
  for (int r = 0; r < 4; ++r) {
    std::snprintf(line, sizeof line, "%s%.15g, %.15g, %.15g, %.15g", r == 0 ? "" : ",\n         ", t(r, 0), t(r, 1),
                  t(r, 2), t(r, 3));
    out << line;
  }
  const PinholeIntrinsics& k = camera.intrinsics;
  std::snprintf(line, sizeof line, "[%.10g, %.10g, %.10g, %.10g]", k.fx, k.fy, k.cx, k.cy);
  out << "]\n\n# Camera specific definitions.\nrate_hz: " << rate_hz << "\nresolution: [" << camera.width << ", "
      << camera.height << "]\ncamera_model: pinhole\nintrinsics: " << line
      << " #fu, fv, cu, cv\ndistortion_model: radial-tangential\ndistortion_coefficients: [0.0, 0.0, 0.0, 0.0]\n";
  if (!out) throw Error("EuRoC writer: cannot write " + path);
}

long long nanoseconds(double time_s) { return std::llround(time_s * 1e9); }

}  // namespace

EurocWriter::EurocWriter(const std::string& directory, const Rig& rig, double rate_hz)
    : directory_(directory), cameras_(static_cast<int>(rig.cameras.size())) {
  rig.validate();
  std::error_code error;
  for (int k = 0; k < cameras_; ++k) {
    std::filesystem::create_directories(cameraDirectory(directory, k) + "/data", error);
    if (error)
      throw Error("EuRoC writer: cannot create " + cameraDirectory(directory, k) + "/data: " + error.message());
    const Eigen::Isometry3d bodyFromCamera =
        k == 0 ? Eigen::Isometry3d::Identity() : rig.cameraFromWorld(Eigen::Isometry3d::Identity(), k).inverse();
    writeSensorYaml(cameraDirectory(directory, k) + "/sensor.yaml", k, rig.cameras[k], bodyFromCamera, rate_hz);
    dataCsv_.push_back(openFile(cameraDirectory(directory, k) + "/data.csv"));
    dataCsv_.back() << "#timestamp [ns],filename\n";
  }
  std::ofstream body = openFile(directory + "/mav0/body.yaml");
  body << "%YAML:1.0\ncomment: lrsvo synthetic flight; the body frame is cam0's\n";
  groundTruth_ = openFile(directory + "/groundtruth_cam0_tum.txt");
  groundTruth_ << "# timestamp(s) tx ty tz qx qy qz qw (world-from-cam0)\n";
  extrinsics_ = openFile(directory + "/true_extrinsics.csv");
  extrinsics_ << "#timestamp [ns],camera,x [m],y [m],z [m],roll [rad],pitch [rad],yaw [rad]\n";
}

void EurocWriter::write(const StereoFrame& frame, const Eigen::Isometry3d& worldFromBase,
                        const std::vector<VertexStereoExtrinsic::Vector6>& trueExtrinsics) {
  if (frame.cameraCount() != cameras_ || static_cast<int>(trueExtrinsics.size()) != cameras_ - 1)
    throw Error("EuRoC writer: a frame needs " + std::to_string(cameras_) + " images and " +
                std::to_string(cameras_ - 1) + " extrinsics");
  const long long ns = nanoseconds(frame.time_s);
  const std::string file = std::to_string(ns) + ".png";
  for (int k = 0; k < cameras_; ++k) {
    const std::string path = cameraDirectory(directory_, k) + "/data/" + file;
    if (!cv::imwrite(path, frame.image(k))) throw Error("EuRoC writer: cannot write " + path);
    dataCsv_[k] << ns << ',' << file << '\n';
  }
  const Eigen::Vector3d p = worldFromBase.translation();
  const Eigen::Quaterniond q(worldFromBase.linear());
  char line[256];
  std::snprintf(line, sizeof line, "%.9f %.9f %.9f %.9f %.12f %.12f %.12f %.12f\n", ns * 1e-9, p.x(), p.y(), p.z(),
                q.x(), q.y(), q.z(), q.w());
  groundTruth_ << line;
  for (int k = 1; k < cameras_; ++k) {
    const VertexStereoExtrinsic::Vector6& s = trueExtrinsics[k - 1];
    std::snprintf(line, sizeof line, "%lld,%d,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g\n", ns, k, s[0], s[1], s[2], s[3],
                  s[4], s[5]);
    extrinsics_ << line;
  }
  for (std::ofstream* out : {&groundTruth_, &extrinsics_})
    if (!*out) throw Error("EuRoC writer: cannot write to " + directory_);
}

}  // namespace lrsvo
