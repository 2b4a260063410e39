#include "lrsvo/frontend/datasets/gtsam_stereo_vo.h"

#include <cmath>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>

#include <Eigen/Geometry>

#include "lrsvo/edges/edge_project_base.h"
#include "lrsvo/edges/edge_project_secondary.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/vertices/vertex_point3.h"

namespace lrsvo {

namespace {

// Reads the whitespace-separated numbers of each non-empty line.
class NumberLines {
 public:
  explicit NumberLines(const std::string& path) : path_(path), in_(path) {
    if (!in_) throw Error("cannot open " + path);
  }
  // Next non-empty line as numbers; false at the end of the file.
  bool next(std::vector<double>& values) {
    std::string text;
    while (std::getline(in_, text)) {
      ++line_;
      std::istringstream fields(text);
      values.clear();
      std::string token;
      while (fields >> token) {
        char* end = nullptr;
        const double value = std::strtod(token.c_str(), &end);
        if (end == token.c_str() || *end != '\0') fail("malformed number '" + token + "'");
        if (!std::isfinite(value)) fail("value '" + token + "' is not finite");
        values.push_back(value);
      }
      if (!values.empty()) return true;
    }
    return false;
  }
  [[noreturn]] void fail(const std::string& what) const { throw ParseError(path_, line_, what); }
  // An id read as a number: a whole number that fits an int, else a failure naming `what`.
  int id(double value, const std::string& what) const {
    if (!(value == std::floor(value) && value >= std::numeric_limits<int>::min() &&
          value <= std::numeric_limits<int>::max()))
      fail(what + " " + std::to_string(value) + " is not a whole number within int's range");
    return static_cast<int>(value);
  }

 private:
  std::string path_;
  std::ifstream in_;
  int line_ = 0;
};

}  // namespace

StereoVoProblem loadGtsamStereoVo(const std::string& directory, const std::string& set) {
  StereoVoProblem problem;
  std::vector<double> v;

  NumberLines calibration(directory + "/VO_calibration.txt");
  if (!calibration.next(v) || v.size() != 6) calibration.fail("expected fx fy skew u0 v0 baseline");
  if (v[2] != 0.0) calibration.fail("non-zero skew is not supported by the pinhole model");
  if (!(v[0] > 0 && v[1] > 0 && v[5] > 0)) calibration.fail("focal lengths and baseline must be positive");
  problem.intrinsics = {v[0], v[1], v[3], v[4]};
  problem.baseline = v[5];

  VertexStereoExtrinsic::Vector6 rig;
  rig << problem.baseline, 0.0, 0.0, 0.0, 0.0, 0.0;
  problem.extrinsic = problem.graph.addVertex(std::make_unique<VertexStereoExtrinsic>(0, rig));
  problem.extrinsic->setFixed(true);

  std::map<int, VertexPose*> posesById;
  NumberLines poses(directory + "/VO_camera_poses_" + set + ".txt");
  while (poses.next(v)) {
    if (v.size() != 17) poses.fail("expected a pose id and 16 numbers of a 4x4 matrix");
    Eigen::Matrix4d worldFromCamera = Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(v.data() + 1);
    const Eigen::Matrix3d r = worldFromCamera.topLeftCorner<3, 3>();
    if (!(r.transpose() * r).isIdentity(1e-4)) poses.fail("the pose's rotation is not orthonormal");
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = Eigen::Quaterniond(r).normalized().toRotationMatrix();
    pose.translation() = worldFromCamera.topRightCorner<3, 1>();
    const int id = poses.id(v[0], "pose id");
    if (posesById.count(id)) poses.fail("duplicate pose id " + std::to_string(id));
    auto* vertex = problem.graph.addVertex(
        std::make_unique<VertexPose>(static_cast<int>(problem.poses.size()) + 1, pose.inverse()));
    vertex->setFixed(problem.poses.empty());
    problem.poses.push_back(vertex);
    posesById[id] = vertex;
  }
  if (problem.poses.empty()) throw Error(directory + ": no poses in VO_camera_poses_" + set + ".txt");

  // Pixel residuals in (u, v) per camera; v is shared, so half its weight each.
  Eigen::Matrix2d information = Eigen::Matrix2d::Identity();
  information(1, 1) = 0.5;
  int nextId = static_cast<int>(problem.poses.size()) + 1;
  NumberLines factors(directory + "/VO_stereo_factors_" + set + ".txt");
  while (factors.next(v)) {
    if (v.size() != 8) factors.fail("expected pose landmark uL uR v X Y Z");
    const int poseId = factors.id(v[0], "pose id");
    auto pose = posesById.find(poseId);
    if (pose == posesById.end()) factors.fail("unknown pose id " + std::to_string(poseId));
    const int landmark = factors.id(v[1], "landmark id");
    auto [entry, inserted] = problem.landmarkVertexIds.emplace(landmark, nextId);
    if (inserted) {
      const Eigen::Vector3d inWorld = pose->second->cameraFromWorld().inverse() * Eigen::Vector3d(v[5], v[6], v[7]);
      problem.graph.addVertex(std::make_unique<VertexPoint3>(nextId++, inWorld));
    }
    Vertex* point = problem.graph.vertex(entry->second);

    auto left = std::make_unique<EdgeProjectBase>(problem.intrinsics);
    left->setVertex(0, pose->second);
    left->setVertex(1, point);
    left->setMeasurement(Eigen::Vector2d(v[2], v[4]));
    left->setInformation(information);
    problem.graph.addEdge(std::move(left));

    auto right = std::make_unique<EdgeProjectSecondary>(SecondaryCamera{1, problem.intrinsics});
    right->setVertex(0, pose->second);
    right->setVertex(1, point);
    right->setVertex(2, problem.extrinsic);
    right->setMeasurement(Eigen::Vector2d(v[3], v[4]));
    right->setInformation(information);
    problem.graph.addEdge(std::move(right));
    ++problem.factorCount;
  }
  return problem;
}

}  // namespace lrsvo
