#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Geometry>

namespace lrsvo {

// A camera trajectory: poses world-from-camera (TUM's and KITTI's convention)
// with their times; the two vectors are parallel.
struct Trajectory {
  std::vector<double> times_s;
  std::vector<Eigen::Isometry3d> worldFromCamera;

  std::size_t size() const { return worldFromCamera.size(); }
  void add(double time_s, const Eigen::Isometry3d& pose) {
    times_s.push_back(time_s);
    worldFromCamera.push_back(pose);
  }
};

enum class PoseFileFormat { kTum, kKitti };

// "tum" or "kitti"; throws lrsvo::Error naming the accepted names otherwise.
PoseFileFormat poseFileFormatFromName(const std::string& name);
// The format of a pose file by the count of numbers on its first data line:
// 8 (TUM) or 12 (KITTI); throws lrsvo::Error for any other count.
PoseFileFormat detectPoseFileFormat(const std::filesystem::path& file);

// TUM: one pose a line, `t tx ty tz qx qy qz qw`, '#' starts a comment.
// Quaternions are normalised; zero-length ones, NaN and malformed lines throw
// lrsvo::ParseError (file and line).
Trajectory readTumTrajectory(const std::filesystem::path& file);
void writeTumTrajectory(const std::filesystem::path& file, const Trajectory& trajectory);

// KITTI: one pose a line, the 12 numbers of the 3x4 matrix [R | t] row by row.
// Times come from `timesFile` (one a line, as many as poses) when given, else
// they are the pose indices 0, 1, 2, ... . The rotation is projected on SO(3).
Trajectory readKittiTrajectory(const std::filesystem::path& file, const std::filesystem::path& timesFile = {});
void writeKittiTrajectory(const std::filesystem::path& file, const Trajectory& trajectory);

}  // namespace lrsvo
