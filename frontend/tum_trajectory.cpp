#include "frontend/tum_trajectory.h"

#include <fstream>
#include <sstream>

#include "graph/error.h"

namespace lrsvo {

std::vector<TimedPose> readTumTrajectory(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error("TUM trajectory: cannot open " + path);
  std::vector<TimedPose> poses;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::size_t hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::istringstream fields(line);
    double t, x, y, z, qx, qy, qz, qw;
    if (!(fields >> t)) continue;  // blank or comment line
    if (!(fields >> x >> y >> z >> qx >> qy >> qz >> qw))
      throw ParseError(path, number, "expected 8 numbers: t tx ty tz qx qy qz qw");
    const Eigen::Quaterniond q(qw, qx, qy, qz);
    if (!(q.norm() > 0.5)) throw ParseError(path, number, "the quaternion is not of unit length");
    TimedPose pose;
    pose.time_s = t;
    pose.worldFromCamera.linear() = q.normalized().toRotationMatrix();
    pose.worldFromCamera.translation() = Eigen::Vector3d(x, y, z);
    poses.push_back(pose);
  }
  return poses;
}

}  // namespace lrsvo
