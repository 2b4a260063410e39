#include "lrsvo/frontend/datasets/kitti_reader.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <opencv2/imgcodecs.hpp>

#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

namespace fs = std::filesystem;
using Row12 = std::array<double, 12>;

// calib.txt: "<name>: 12 numbers" per line, by name.
std::map<std::string, Row12> readCalibration(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error("KITTI: cannot open " + path);
  std::map<std::string, Row12> rows;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::istringstream fields(line.substr(colon + 1));
    Row12 row;
    for (double& value : row)
      if (!(fields >> value))
        throw ParseError(path, number, "expected 12 numbers after '" + line.substr(0, colon + 1) + "'");
    rows[line.substr(0, colon)] = row;
  }
  return rows;
}

const Row12& projection(const std::map<std::string, Row12>& rows, const std::string& name, const std::string& path) {
  const auto found = rows.find(name);
  if (found == rows.end()) throw Error("KITTI: " + path + " has no row '" + name + ":'");
  return found->second;
}

std::vector<double> readTimes(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error("KITTI: cannot open " + path);
  std::vector<double> times;
  double t;
  while (in >> t) times.push_back(t);
  if (!in.eof()) throw Error("KITTI: " + path + " holds something other than times in seconds");
  if (times.empty()) throw Error("KITTI: " + path + " lists no frame");
  return times;
}

std::vector<TimedPose> readPoses(const std::string& path, const std::vector<double>& times) {
  std::ifstream in(path);
  if (!in) throw Error("KITTI: cannot open " + path);
  std::vector<TimedPose> poses;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::istringstream fields(line);
    Row12 row;
    if (!(fields >> row[0])) continue;
    for (std::size_t i = 1; i < 12; ++i)
      if (!(fields >> row[i])) throw ParseError(path, number, "expected 12 numbers (a 3x4 matrix by rows)");
    if (poses.size() >= times.size()) throw ParseError(path, number, "more poses than times in times.txt");
    TimedPose pose;
    pose.time_s = times[poses.size()];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) pose.worldFromCamera.matrix()(r, c) = row[static_cast<std::size_t>(4 * r + c)];
    poses.push_back(pose);
  }
  return poses;
}

}  // namespace

KittiSource::KittiSource(const std::string& directory) : directory_(directory) {
  const std::string calibrationPath = directory + "/calib.txt";
  const std::map<std::string, Row12> rows = readCalibration(calibrationPath);
  const Row12& p0 = projection(rows, "P0", calibrationPath);
  const Row12& p1 = projection(rows, "P1", calibrationPath);
  times_ = readTimes(directory + "/times.txt");
  const cv::Mat first = cv::imread(imagePath(0, 0), cv::IMREAD_GRAYSCALE);
  if (first.empty()) throw Error("KITTI: cannot read image " + imagePath(0, 0));
  for (const Row12& p : {p0, p1}) {
    if (!(p[0] > 0.0 && p[5] > 0.0))
      throw Error("KITTI: " + calibrationPath + ": P0 and P1 need positive focal lengths");
    Camera camera;
    camera.intrinsics = {p[0], p[5], p[2], p[6]};
    camera.width = first.cols;
    camera.height = first.rows;
    rig_.cameras.push_back(camera);
  }
  const double baseline = -p1[3] / p1[0];
  if (!(baseline > 0.0)) throw Error("KITTI: " + calibrationPath + ": P1 should place camera 1 right of camera 0");
  rig_.extrinsics = {(VertexStereoExtrinsic::Vector6() << baseline, 0, 0, 0, 0, 0).finished()};
  rig_.validate();

  fs::path sequence = fs::absolute(directory).lexically_normal();
  if (sequence.filename().empty()) sequence = sequence.parent_path();  // "SEQ/" names SEQ
  const fs::path local = sequence / "poses.txt";
  const fs::path dataset = sequence.parent_path().parent_path() / "poses" / (sequence.filename().string() + ".txt");
  if (fs::exists(local))
    truth_.poses = readPoses(local.string(), times_);
  else if (fs::exists(dataset))
    truth_.poses = readPoses(dataset.string(), times_);
}

std::string KittiSource::imagePath(int camera, int frame) const {
  char name[32];
  std::snprintf(name, sizeof name, "/image_%d/%06d.png", camera, frame);
  return directory_ + name;
}

std::optional<StereoFrame> KittiSource::next() {
  if (next_ >= frameCount()) return std::nullopt;
  StereoFrame frame;
  frame.index = next_;
  frame.time_s = times_[static_cast<std::size_t>(next_)];
  for (int c = 0; c < 2; ++c) {
    cv::Mat image = cv::imread(imagePath(c, next_), cv::IMREAD_GRAYSCALE);
    if (image.empty() && frame.defect.empty()) frame.defect = "cannot read image " + imagePath(c, next_);
    if (!image.empty() && (image.cols != rig_.cameras[0].width || image.rows != rig_.cameras[0].height) &&
        frame.defect.empty())
      frame.defect = "image " + imagePath(c, next_) + " differs in size from the sequence's first image";
    frame.images.push_back(std::move(image));
  }
  ++next_;
  return frame;
}

}  // namespace lrsvo
