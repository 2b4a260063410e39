#include "lrsvo/frontend/datasets/pose_file.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

#include <Eigen/SVD>

#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

constexpr int kTumColumns = 8;
constexpr int kKittiColumns = 12;
// How far from orthonormal a KITTI rotation may be (files print 6-9 digits) before it is rejected.
constexpr double kRotationTolerance = 1e-3;

std::ifstream openForReading(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw Error("cannot open pose file " + file.string());
  return in;
}

std::ofstream openForWriting(const std::filesystem::path& file) {
  std::ofstream out(file);
  if (!out) throw Error("cannot write pose file " + file.string());
  out << std::setprecision(std::numeric_limits<double>::max_digits10);
  return out;
}

// A data line's text without its comment and surrounding blanks ("" for a blank or comment line).
std::string dataPart(const std::string& line) {
  const std::string text = line.substr(0, line.find('#'));
  const std::size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

// The finite numbers of a data line, split at blanks; anything else is a ParseError.
std::vector<double> parseNumbers(const std::string& text, const std::string& file, int lineNumber) {
  std::vector<double> numbers;
  std::istringstream words(text);
  std::string word;
  while (words >> word) {
    char* end = nullptr;
    const double value = std::strtod(word.c_str(), &end);
    if (end == word.c_str() || *end != '\0') throw ParseError(file, lineNumber, "'" + word + "' is not a number");
    if (!std::isfinite(value)) throw ParseError(file, lineNumber, "'" + word + "': expected a finite number");
    numbers.push_back(value);
  }
  return numbers;
}

// Calls `use(numbers, lineNumber)` for every data line of `file`, each with exactly `columns` numbers.
template <typename Use>
void forEachDataLine(const std::filesystem::path& file, int columns, const std::string& layout, Use use) {
  std::ifstream in = openForReading(file);
  std::string line;
  for (int lineNumber = 1; std::getline(in, line); ++lineNumber) {
    const std::string text = dataPart(line);
    if (text.empty()) continue;
    const std::vector<double> numbers = parseNumbers(text, file.string(), lineNumber);
    if (static_cast<int>(numbers.size()) != columns)
      throw ParseError(
          file.string(), lineNumber,
          std::to_string(numbers.size()) + " numbers, expected " + std::to_string(columns) + " (" + layout + ")");
    use(numbers, lineNumber);
  }
}

// The rotation nearest to `m` (SVD), or a ParseError when `m` is not close to one.
Eigen::Matrix3d nearestRotation(const Eigen::Matrix3d& m, const std::string& file, int lineNumber) {
  if ((m.transpose() * m - Eigen::Matrix3d::Identity()).norm() > kRotationTolerance || m.determinant() < 0.0)
    throw ParseError(file, lineNumber, "the 3x3 part is not a rotation matrix (R^T R != I or det R < 0)");
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(m, Eigen::ComputeFullU | Eigen::ComputeFullV);
  return svd.matrixU() * svd.matrixV().transpose();
}

}  // namespace

PoseFileFormat poseFileFormatFromName(const std::string& name) {
  if (name == "tum") return PoseFileFormat::kTum;
  if (name == "kitti") return PoseFileFormat::kKitti;
  throw Error("unknown pose file format '" + name + "'; expected tum or kitti");
}

PoseFileFormat detectPoseFileFormat(const std::filesystem::path& file) {
  std::ifstream in = openForReading(file);
  std::string line;
  for (int lineNumber = 1; std::getline(in, line); ++lineNumber) {
    const std::string text = dataPart(line);
    if (text.empty()) continue;
    const std::size_t count = parseNumbers(text, file.string(), lineNumber).size();
    if (count == kTumColumns) return PoseFileFormat::kTum;
    if (count == kKittiColumns) return PoseFileFormat::kKitti;
    throw ParseError(file.string(), lineNumber,
                     std::to_string(count) +
                         " numbers: neither TUM (8: t tx ty tz qx qy qz qw) nor KITTI (12: 3x4 "
                         "matrix row by row)");
  }
  throw Error("pose file " + file.string() + " holds no pose");
}

Trajectory readTumTrajectory(const std::filesystem::path& file) {
  Trajectory trajectory;
  forEachDataLine(file, kTumColumns, "t tx ty tz qx qy qz qw", [&](const std::vector<double>& n, int lineNumber) {
    Eigen::Quaterniond q(n[7], n[4], n[5], n[6]);
    if (q.norm() < 1e-6) throw ParseError(file.string(), lineNumber, "zero quaternion, expected a unit one");
    q.normalize();
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = q.toRotationMatrix();
    pose.translation() = Eigen::Vector3d(n[1], n[2], n[3]);
    trajectory.add(n[0], pose);
  });
  return trajectory;
}

void writeTumTrajectory(const std::filesystem::path& file, const Trajectory& trajectory) {
  std::ofstream out = openForWriting(file);
  out << "# t tx ty tz qx qy qz qw (world-from-camera)\n";
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    const Eigen::Vector3d t = trajectory.worldFromCamera[i].translation();
    const Eigen::Quaterniond q(trajectory.worldFromCamera[i].linear());
    out << trajectory.times_s[i] << ' ' << t.x() << ' ' << t.y() << ' ' << t.z() << ' ' << q.x() << ' ' << q.y() << ' '
        << q.z() << ' ' << q.w() << '\n';
  }
  if (!out) throw Error("error writing pose file " + file.string());
}

Trajectory readKittiTrajectory(const std::filesystem::path& file, const std::filesystem::path& timesFile) {
  Trajectory trajectory;
  forEachDataLine(file, kKittiColumns, "3x4 matrix row by row", [&](const std::vector<double>& n, int lineNumber) {
    Eigen::Matrix3d m;
    m << n[0], n[1], n[2], n[4], n[5], n[6], n[8], n[9], n[10];
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = nearestRotation(m, file.string(), lineNumber);
    pose.translation() = Eigen::Vector3d(n[3], n[7], n[11]);
    trajectory.add(static_cast<double>(trajectory.size()), pose);
  });
  if (timesFile.empty()) return trajectory;
  std::vector<double> times;
  forEachDataLine(timesFile, 1, "a time in seconds", [&](const std::vector<double>& n, int) { times.push_back(n[0]); });
  if (times.size() != trajectory.size())
    throw Error("times file " + timesFile.string() + " holds " + std::to_string(times.size()) + " times for the " +
                std::to_string(trajectory.size()) + " poses of " + file.string());
  trajectory.times_s = std::move(times);
  return trajectory;
}

void writeKittiTrajectory(const std::filesystem::path& file, const Trajectory& trajectory) {
  std::ofstream out = openForWriting(file);
  for (const Eigen::Isometry3d& pose : trajectory.worldFromCamera) {
    const Eigen::Matrix<double, 3, 4> m = pose.matrix().topRows<3>();
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) out << m(r, c) << (r == 2 && c == 3 ? '\n' : ' ');
  }
  if (!out) throw Error("error writing pose file " + file.string());
}

}  // namespace lrsvo
