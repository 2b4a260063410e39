#include "lrsvo/frontend/datasets/euroc_reader.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <opencv2/imgcodecs.hpp>

#include "lrsvo/frontend/datasets/pose_file.h"
#include "lrsvo/frontend/odometry/rig_extrinsic.h"
#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

namespace fs = std::filesystem;

std::string readText(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error("EuRoC: cannot open " + path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Where `key:` starts a word in the text (from `from`), or npos.
std::size_t findKey(const std::string& text, const std::string& key, std::size_t from = 0) {
  for (std::size_t at = text.find(key + ":", from); at != std::string::npos; at = text.find(key + ":", at + 1))
    if (at == 0 || text[at - 1] == '\n' || text[at - 1] == ' ') return at;
  return std::string::npos;
}

// The numbers of the bracketed list after `key:` (searched from `from`),
// which may span lines and carry '#' comments after it.
std::vector<double> listAfter(const std::string& text, const std::string& key, const std::string& path,
                              std::size_t from) {
  const std::size_t at = findKey(text, key, from);
  if (at == std::string::npos) throw Error("EuRoC: " + path + " has no key '" + key + "'");
  const std::size_t open = text.find('[', at), close = text.find(']', at);
  const std::size_t lineEnd = text.find('\n', at);
  if (open == std::string::npos || close == std::string::npos || close < open || open > lineEnd)
    throw Error("EuRoC: " + path + ": key '" + key + "' is not followed by a [list]");
  std::string list = text.substr(open + 1, close - open - 1);
  for (char& c : list)
    if (c == ',') c = ' ';
  std::istringstream in(list);
  std::vector<double> numbers;
  double value;
  while (in >> value) numbers.push_back(value);
  if (!in.eof()) throw Error("EuRoC: " + path + ": key '" + key + "' holds something other than numbers");
  return numbers;
}

std::vector<double> numberList(const std::string& text, const std::string& key, const std::string& path,
                               std::size_t count, std::size_t from = 0) {
  std::vector<double> numbers = listAfter(text, key, path, from);
  if (numbers.size() != count)
    throw Error("EuRoC: " + path + ": key '" + key + "' should hold " + std::to_string(count) + " numbers, has " +
                std::to_string(numbers.size()));
  return numbers;
}

// data.csv: "#timestamp [ns],filename" rows, by timestamp.
std::map<long long, std::string> readImageList(const std::string& cameraDirectory) {
  const std::string path = cameraDirectory + "/data.csv";
  std::ifstream in(path);
  if (!in) throw Error("EuRoC: cannot open " + path);
  std::map<long long, std::string> images;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.empty() || line[0] == '#') continue;
    if (line.back() == '\r') line.pop_back();
    const std::size_t comma = line.find(',');
    if (comma == std::string::npos) throw ParseError(path, number, "expected 'timestamp_ns,filename'");
    std::string file = line.substr(comma + 1);
    file.erase(0, file.find_first_not_of(" \t"));
    file.erase(file.find_last_not_of(" \t") + 1);
    if (file.empty()) throw ParseError(path, number, "no file name after the timestamp");
    try {
      images[std::stoll(line.substr(0, comma))] = cameraDirectory + "/data/" + file;
    } catch (const std::logic_error&) {
      throw ParseError(path, number, "the timestamp is not an integer number of nanoseconds");
    }
  }
  if (images.empty()) throw Error("EuRoC: " + path + " lists no image");
  return images;
}

// The word after `key:` on its line, without quotes or a '#' comment; empty
// when the key is absent.
std::string wordAfter(const std::string& text, const std::string& key) {
  const std::size_t at = findKey(text, key);
  if (at == std::string::npos) return "";
  const std::size_t lineEnd = std::min(text.find('\n', at), text.size());
  std::string value = text.substr(at + key.size() + 1, lineEnd - at - key.size() - 1);
  value = value.substr(0, value.find('#'));
  std::istringstream words(value);
  std::string word;
  words >> word;
  if (word.size() >= 2 && (word.front() == '"' || word.front() == '\'') && word.back() == word.front())
    word = word.substr(1, word.size() - 2);
  return word;
}

// distortion_model and distortion_coefficients: radial-tangential (also
// Kalibr's "radtan"; [k1 k2 p1 p2] or with k3), equidistant ([k1 k2 k3 k4]),
// or none. A file without distortion_model is radial-tangential, as EuRoC's are.
LensDistortion readDistortion(const std::string& text, const std::string& path) {
  const std::string model = wordAfter(text, "distortion_model");
  LensDistortion distortion;
  if (model == "none") return distortion;
  const std::vector<double> d = listAfter(text, "distortion_coefficients", path, 0);
  if (model.empty() || model == "radial-tangential" || model == "radtan") {
    if (d.size() != 4 && d.size() != 5)
      throw Error("EuRoC: " + path +
                  ": key 'distortion_coefficients' should hold 4 numbers (k1 k2 p1 p2) or 5 (and k3), has " +
                  std::to_string(d.size()));
  } else if (model == "equidistant") {
    if (d.size() != 4)
      throw Error(
          "EuRoC: " + path +
          ": key 'distortion_coefficients' should hold 4 numbers (k1 k2 k3 k4) for the equidistant model, has " +
          std::to_string(d.size()));
    distortion.model = LensDistortion::Model::kEquidistant;
  } else {
    throw Error("EuRoC: " + path + ": distortion_model '" + model +
                "' is not supported (radial-tangential or radtan, equidistant, none)");
  }
  std::copy(d.begin(), d.end(), distortion.coefficients.begin());
  return distortion;
}

// mav0/state_groundtruth_estimate0/data.csv, EuRoC's own ground truth: per row
// the time (ns), the body's position p_RS_R (m) and orientation q_RS (w x y z)
// in the world frame R, then velocities and biases, which are not read.
std::vector<TimedPose> readStateGroundTruth(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error("EuRoC: cannot open " + path);
  std::vector<TimedPose> poses;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.empty() || line[0] == '#') continue;
    for (char& c : line)
      if (c == ',') c = ' ';
    std::istringstream fields(line);
    long long stamp = 0;
    double v[7];
    if (!(fields >> stamp >> v[0] >> v[1] >> v[2] >> v[3] >> v[4] >> v[5] >> v[6]))
      throw ParseError(path, number, "expected 'timestamp_ns, p_x, p_y, p_z, q_w, q_x, q_y, q_z, ...'");
    const Eigen::Quaterniond q(v[3], v[4], v[5], v[6]);
    if (!(q.norm() > 0.5 && q.norm() < 2.0))  // also false for NaN
      throw ParseError(path, number, "the orientation quaternion is not near unit length");
    TimedPose pose;
    pose.time_s = static_cast<double>(stamp) * 1e-9;
    pose.worldFromCamera.linear() = q.normalized().toRotationMatrix();
    pose.worldFromCamera.translation() = Eigen::Vector3d(v[0], v[1], v[2]);
    poses.push_back(pose);
  }
  if (poses.empty()) throw Error("EuRoC: " + path + " holds no pose");
  return poses;
}

}  // namespace

EurocCameraCalibration readEurocSensor(const std::string& path) {
  const std::string text = readText(path);
  const std::string cameraModel = wordAfter(text, "camera_model");
  if (!cameraModel.empty() && cameraModel != "pinhole")
    throw Error("EuRoC: " + path + ": camera_model '" + cameraModel + "' is not supported (pinhole)");
  const std::vector<double> k = numberList(text, "intrinsics", path, 4);
  const LensDistortion distortion = readDistortion(text, path);
  const std::vector<double> resolution = numberList(text, "resolution", path, 2);
  const std::size_t tbs = text.find("T_BS:");
  if (tbs == std::string::npos) throw Error("EuRoC: " + path + " has no key 'T_BS'");
  const std::vector<double> t = numberList(text, "data", path, 16, tbs);
  EurocCameraCalibration calibration;
  calibration.camera.intrinsics = {k[0], k[1], k[2], k[3]};
  calibration.camera.width = static_cast<int>(resolution[0]);
  calibration.camera.height = static_cast<int>(resolution[1]);
  calibration.distortion = distortion;
  Eigen::Matrix4d m;
  for (int i = 0; i < 16; ++i) m(i / 4, i % 4) = t[static_cast<std::size_t>(i)];
  calibration.bodyFromSensor.matrix() = m;
  return calibration;
}

std::vector<EurocSource::FramePaths> EurocSource::pairByTime(const std::map<long long, std::string>& cam0,
                                                             const std::map<long long, std::string>& cam1) {
  // Only the stretch both cameras recorded holds frames: one camera's images
  // before the other's first or after its last are not missing partners.
  const long long first = std::max(cam0.begin()->first, cam1.begin()->first) - kStereoSyncTolerance_ns;
  const long long last = std::min(cam0.rbegin()->first, cam1.rbegin()->first) + kStereoSyncTolerance_ns;
  std::vector<FramePaths> frames;
  auto a = cam0.lower_bound(first), b = cam1.lower_bound(first);
  const auto aEnd = cam0.upper_bound(last), bEnd = cam1.upper_bound(last);
  while (a != aEnd || b != bEnd) {
    if (a != aEnd && b != bEnd && std::llabs(a->first - b->first) <= kStereoSyncTolerance_ns) {
      frames.push_back({a->first * 1e-9, {a->second, b->second}});
      ++a, ++b;
    } else if (b == bEnd || (a != aEnd && a->first < b->first)) {
      frames.push_back({a->first * 1e-9, {a->second, ""}});
      ++a;
    } else {
      frames.push_back({b->first * 1e-9, {"", b->second}});
      ++b;
    }
  }
  return frames;
}

EurocSource::EurocSource(const std::string& directory) : directory_(directory) {
  const std::string mav = directory + "/mav0";
  if (!fs::is_directory(mav)) throw Error("EuRoC: no directory " + mav);
  std::array<EurocCameraCalibration, 2> calibration;
  std::array<std::map<long long, std::string>, 2> images;
  for (int c = 0; c < 2; ++c) {
    const std::string camera = mav + "/cam" + std::to_string(c);
    calibration[static_cast<std::size_t>(c)] = readEurocSensor(camera + "/sensor.yaml");
    images[static_cast<std::size_t>(c)] = readImageList(camera);
  }
  rig_.cameras = {calibration[0].camera, calibration[1].camera};
  rig_.extrinsics = {extrinsicFromPoses(calibration[0].bodyFromSensor, calibration[1].bodyFromSensor)};
  rig_.validate();
  distortion_ = {calibration[0].distortion, calibration[1].distortion};
  frames_ = pairByTime(images[0], images[1]);
  if (std::none_of(frames_.begin(), frames_.end(), [](const FramePaths& f) { return f.paired(); }))
    throw Error("EuRoC: no cam0 image has a cam1 image within " + std::to_string(kStereoSyncTolerance_ns / 1000) +
                " us of its timestamp in " + mav);

  const std::string cameraTruth = directory + "/groundtruth_cam0_tum.txt";
  const std::string bodyTruth = directory + "/groundtruth_body_tum.txt";
  auto readTruth = [&](const std::string& file, const Eigen::Isometry3d& bodyFromCamera) {
    const Trajectory trajectory = readTumTrajectory(file);
    for (std::size_t i = 0; i < trajectory.size(); ++i)
      truth_.poses.push_back({trajectory.times_s[i], trajectory.worldFromCamera[i] * bodyFromCamera});
  };
  const std::string stateTruth = mav + "/state_groundtruth_estimate0/data.csv";
  if (fs::exists(cameraTruth)) {
    readTruth(cameraTruth, Eigen::Isometry3d::Identity());
  } else if (fs::exists(bodyTruth)) {
    readTruth(bodyTruth, calibration[0].bodyFromSensor);
  } else if (fs::exists(stateTruth)) {
    for (TimedPose pose : readStateGroundTruth(stateTruth)) {
      pose.worldFromCamera = pose.worldFromCamera * calibration[0].bodyFromSensor;
      truth_.poses.push_back(pose);
    }
  }
}

std::optional<StereoFrame> EurocSource::next() {
  if (next_ >= frames_.size()) return std::nullopt;
  const FramePaths& paths = frames_[next_];
  StereoFrame frame;
  frame.index = static_cast<int>(next_++);
  frame.time_s = paths.time_s;
  for (std::size_t c = 0; c < 2; ++c) {
    if (paths.images[c].empty()) {
      if (frame.defect.empty())
        frame.defect = "no cam" + std::to_string(c) + " image within " +
                       std::to_string(kStereoSyncTolerance_ns / 1000) + " us of cam" + std::to_string(1 - c) + "'s";
      frame.images.emplace_back();
      continue;
    }
    cv::Mat image = cv::imread(paths.images[c], cv::IMREAD_GRAYSCALE);
    const Camera& camera = rig_.cameras[c];
    if (image.empty() && frame.defect.empty()) frame.defect = "cannot read image " + paths.images[c];
    if (!image.empty() && (image.cols != camera.width || image.rows != camera.height) && frame.defect.empty())
      frame.defect = "image " + paths.images[c] + " is " + std::to_string(image.cols) + "x" +
                     std::to_string(image.rows) + ", sensor.yaml says " + std::to_string(camera.width) + "x" +
                     std::to_string(camera.height);
    frame.images.push_back(std::move(image));
  }
  return frame;
}

}  // namespace lrsvo
