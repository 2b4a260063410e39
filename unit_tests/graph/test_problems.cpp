#include "unit_tests/graph/test_problems.h"

#include <memory>
#include <random>
#include <vector>

#include "lrsvo/constraints/constraint_types.h"
#include "lrsvo/edges/edge_bal_projection.h"
#include "lrsvo/edges/edge_types.h"
#include "lrsvo/graph/edge_io.h"
#include "lrsvo/graph/graph_file.h"
#include "lrsvo/graph/registry.h"
#include "lrsvo/vertices/so3.h"
#include "lrsvo/vertices/vertex_bal_camera.h"

namespace lrsvo::test {

namespace {

// d(f X.xy / X.z) / dX.
Eigen::Matrix<double, 2, 3> projectionDerivative(double focal, const Eigen::Vector3d& x) {
  const double iz = 1.0 / x.z();
  Eigen::Matrix<double, 2, 3> d;
  d << focal * iz, 0, -focal * x.x() * iz * iz, 0, focal * iz, -focal * x.y() * iz * iz;
  return d;
}

Eigen::Vector3d cameraPoint(const VertexPose& pose, const VertexPoint3& point) {
  return pose.rotation() * point.estimate() + pose.translation();
}

void readFocal(std::istream& in, double& focal, const char* tag) {
  focal = readNumber(in, tag);
  if (!(focal > 0.0)) throw Error(std::string(tag) + ": focal length must be positive");
}

// The kernel of the k-th edge: a fixed name, or "cycle" through all of them and none.
std::shared_ptr<RobustKernel> kernelFor(const std::string& kernel, double delta, int k) {
  static const char* const kCycle[] = {"Huber", "Cauchy", "Tukey", ""};
  const std::string name = kernel == "cycle" ? kCycle[k % 4] : kernel;
  return name.empty() ? nullptr : makeRobustKernel(name, delta);
}

Eigen::Matrix2d randomInformation(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> diagonal(0.5, 1.5), offDiagonal(-0.3, 0.3);
  Eigen::Matrix2d lower;
  lower << diagonal(rng), 0.0, offDiagonal(rng), diagonal(rng);
  return lower * lower.transpose();
}

// A point in a box around (centreX, 0, 0), about 10 m in front of the cameras.
Eigen::Vector3d pointNear(double centreX, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> spread(-2.0, 2.0), depth(-1.0, 1.0);
  return {centreX + spread(rng), spread(rng), depth(rng)};
}

Eigen::Vector3d gaussianVector(std::mt19937_64& rng, double sigma) {
  std::normal_distribution<double> unit(0.0, 1.0);
  return Eigen::Vector3d{unit(rng), unit(rng), unit(rng)} * sigma;
}

// Which observers see point j: a band of `perPoint` consecutive ones.
int bandStart(int j, int observers, int perPoint) { return j % (observers - perPoint + 1); }

}  // namespace

void EdgePinhole::computeResidual(Residual& residual) const {
  const Eigen::Vector3d x = cameraPoint(*vertexAs<0>(), *vertexAs<1>());
  residual = focal * x.head<2>() / x.z() - measurement_;
}

void EdgePinhole::computeJacobians() {
  const Eigen::Vector3d x = cameraPoint(*vertexAs<0>(), *vertexAs<1>());
  const Eigen::Matrix<double, 2, 3> du_dx = projectionDerivative(focal, x);
  // X_c' = Exp(dphi) X_c + dt: dX_c/d(dt) = I, dX_c/d(dphi) = -[X_c]x.
  jacobian<0>().leftCols<3>() = du_dx;
  jacobian<0>().rightCols<3>() = -du_dx * skew(x);
  jacobian<1>() = du_dx * vertexAs<0>()->rotation();
}

void EdgePinhole::writeParameters(std::ostream& out) const { writeNumber(out, focal); }
void EdgePinhole::readParameters(std::istream& in) { readFocal(in, focal, kTypeTag); }

void EdgeScaledPinhole::computeResidual(Residual& residual) const {
  const Eigen::Vector3d x = cameraPoint(*vertexAs<0>(), *vertexAs<1>());
  residual = focal * (1.0 + vertexAs<2>()->estimate()[0]) * x.head<2>() / x.z() - measurement_;
}

void EdgeScaledPinhole::computeJacobians() {
  const Eigen::Vector3d x = cameraPoint(*vertexAs<0>(), *vertexAs<1>());
  const double scale = 1.0 + vertexAs<2>()->estimate()[0];
  const Eigen::Matrix<double, 2, 3> du_dx = projectionDerivative(focal * scale, x);
  jacobian<0>().leftCols<3>() = du_dx;
  jacobian<0>().rightCols<3>() = -du_dx * skew(x);
  jacobian<1>() = du_dx * vertexAs<0>()->rotation();
  jacobian<2>() = focal * x.head<2>() / x.z();
}

void EdgeScaledPinhole::writeParameters(std::ostream& out) const { writeNumber(out, focal); }
void EdgeScaledPinhole::readParameters(std::istream& in) { readFocal(in, focal, kTypeTag); }

EdgeQuadraticCost::Gradient EdgeQuadraticCost::stacked() const {
  Gradient x;
  x << vertexAs<0>()->estimate(), vertexAs<1>()->estimate();
  return x;
}

double EdgeQuadraticCost::cost() const {
  const Gradient d = stacked() - centre;
  return 0.5 * d.dot(weight * d);
}

void EdgeQuadraticCost::computeGradientHessian(Gradient& gradient, Hessian& hessian) const {
  gradient = weight * (stacked() - centre);
  hessian = weight;
}

void EdgeQuadraticCost::writeData(std::ostream& out) const {
  writeVector(out, centre);
  writeUpperTriangle(out, weight);
}

void EdgeQuadraticCost::readData(std::istream& in) {
  readVector(in, centre, kTypeTag);
  readUpperTriangle(in, weight, kTypeTag);
}

LRSVO_REGISTER_TYPE(Vertex, VertexFocalScale);
LRSVO_REGISTER_TYPE(Edge, EdgePinhole);
LRSVO_REGISTER_TYPE(Edge, EdgeScaledPinhole);
LRSVO_REGISTER_TYPE(Edge, EdgeQuadraticCost);

int addToyProblem(Graph& graph, const ToyOptions& options) {
  std::mt19937_64 rng(options.seed);
  std::normal_distribution<double> unit(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);

  int id = options.firstId;
  std::vector<VertexPose*> poses;
  for (int i = 0; i < options.poses; ++i) {
    const Eigen::Vector3d centre{i - 0.5 * (options.poses - 1), 0.2 * unit(rng), -10.0 + 0.2 * unit(rng)};
    Eigen::Isometry3d cameraFromWorld = Eigen::Isometry3d::Identity();
    cameraFromWorld.linear() = expSO3(gaussianVector(rng, 0.05));
    cameraFromWorld.translation() = -cameraFromWorld.linear() * centre;
    auto* pose = graph.addVertex(std::make_unique<VertexPose>(id++, cameraFromWorld));
    pose->setFixed(i < options.fixedPoses);
    poses.push_back(pose);
  }
  std::vector<VertexPoint3*> points;
  for (int j = 0; j < options.points; ++j) {
    const int start = bandStart(j, options.poses, options.posesPerPoint);
    const double centreX = start + 0.5 * (options.posesPerPoint - 1) - 0.5 * (options.poses - 1);
    auto* point = graph.addVertex(std::make_unique<VertexPoint3>(id++, pointNear(centreX, rng)));
    point->setFixed(j < options.fixedPoints);
    points.push_back(point);
  }
  VertexFocalScale* scale = options.sharedScale ? graph.addVertex(std::make_unique<VertexFocalScale>(id++)) : nullptr;

  int edgeCount = 0;
  for (int j = 0; j < options.points; ++j) {
    const int start = bandStart(j, options.poses, options.posesPerPoint);
    for (int i = start; i < start + options.posesPerPoint; ++i) {
      auto observe = [&](auto edge) {
        edge->setVertex(0, poses[i]);
        edge->setVertex(1, points[j]);
        Eigen::Vector2d prediction;
        edge->computeResidual(prediction);  // the measurement is still zero
        Eigen::Vector2d measurement = prediction + options.pixelNoise * Eigen::Vector2d{unit(rng), unit(rng)};
        if (uniform(rng) < options.outlierFraction)
          measurement += 30.0 * Eigen::Vector2d{unit(rng), unit(rng)}.normalized();
        edge->setMeasurement(measurement);
        if (options.randomInformation) edge->setInformation(randomInformation(rng));
        edge->setRobustKernel(kernelFor(options.kernel, options.kernelDelta, edgeCount++));
        graph.addEdge(std::move(edge));
      };
      if (scale) {
        auto edge = std::make_unique<EdgeScaledPinhole>();
        edge->setVertex(2, scale);
        observe(std::move(edge));
      } else {
        observe(std::make_unique<EdgePinhole>());
      }
    }
  }

  // Perturb the start of everything that is free.
  for (VertexPose* pose : poses) {
    if (pose->fixed()) continue;
    Eigen::Matrix<double, 6, 1> delta;
    delta << gaussianVector(rng, options.poseNoise), gaussianVector(rng, options.poseNoise);
    pose->oplus(delta.data());
  }
  for (VertexPoint3* point : points)
    if (!point->fixed()) point->setEstimateVector(point->estimate() + gaussianVector(rng, options.pointNoise));
  if (scale) scale->setEstimateVector(Eigen::Matrix<double, 1, 1>(options.scaleNoise * unit(rng)));
  return id;
}

Graph makeToyProblem(const ToyOptions& options) {
  Graph graph;
  addToyProblem(graph, options);
  return graph;
}

int addBalToyProblem(Graph& graph, const BalToyOptions& options) {
  std::mt19937_64 rng(options.seed);
  std::normal_distribution<double> unit(0.0, 1.0);

  int id = options.firstId;
  std::vector<VertexBalCamera*> cameras;
  for (int i = 0; i < options.cameras; ++i) {
    // BAL cameras look down their -z axis: centres above the points.
    const Eigen::Vector3d centre{i - 0.5 * (options.cameras - 1), 0.2 * unit(rng), 10.0 + 0.2 * unit(rng)};
    const Eigen::Vector3d angleAxis = gaussianVector(rng, 0.05);
    Eigen::Matrix<double, 9, 1> camera;
    camera << angleAxis, -expSO3(angleAxis) * centre, 500.0 + 20.0 * unit(rng), 0.05 * unit(rng), 0.01 * unit(rng);
    auto vertex = std::make_unique<VertexBalCamera>(id++);
    vertex->setEstimateVector(camera);
    vertex->setFixed(i < options.fixedCameras);
    cameras.push_back(graph.addVertex(std::move(vertex)));
  }
  std::vector<VertexPoint3*> points;
  for (int j = 0; j < options.points; ++j) {
    const int start = bandStart(j, options.cameras, options.camerasPerPoint);
    const double centreX = start + 0.5 * (options.camerasPerPoint - 1) - 0.5 * (options.cameras - 1);
    points.push_back(graph.addVertex(std::make_unique<VertexPoint3>(id++, pointNear(centreX, rng))));
  }
  int edgeCount = 0;
  for (int j = 0; j < options.points; ++j) {
    const int start = bandStart(j, options.cameras, options.camerasPerPoint);
    for (int i = start; i < start + options.camerasPerPoint; ++i) {
      auto edge = std::make_unique<EdgeBalProjection>();
      edge->setVertex(0, cameras[i]);
      edge->setVertex(1, points[j]);
      Eigen::Vector2d prediction;
      edge->computeResidual(prediction);
      edge->setMeasurement(prediction + options.pixelNoise * Eigen::Vector2d{unit(rng), unit(rng)});
      if (options.randomInformation) edge->setInformation(randomInformation(rng));
      edge->setRobustKernel(kernelFor(options.kernel, options.kernelDelta, edgeCount++));
      graph.addEdge(std::move(edge));
    }
  }
  for (VertexBalCamera* camera : cameras) {
    if (camera->fixed()) continue;
    Eigen::Matrix<double, 9, 1> start = camera->estimate();
    start.head<3>() += gaussianVector(rng, 0.01);
    start.segment<3>(3) += gaussianVector(rng, 0.05);
    camera->setEstimateVector(start);
  }
  for (VertexPoint3* point : points) point->setEstimateVector(point->estimate() + gaussianVector(rng, 0.05));
  return id;
}

Graph makeBalToyProblem(const BalToyOptions& options) {
  Graph graph;
  addBalToyProblem(graph, options);
  return graph;
}

Eigen::MatrixXd denseHessian(const BlockSystem& system) {
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(system.scalarCount(), system.scalarCount());
  for (const BlockSystem::Block& block : system.blocks()) {
    const int rows = system.dim(block.row), cols = system.dim(block.col);
    const Eigen::Map<const Eigen::MatrixXd> values(system.values(block), rows, cols);
    h.block(system.offset(block.row), system.offset(block.col), rows, cols) = values;
    if (block.row != block.col)
      h.block(system.offset(block.col), system.offset(block.row), cols, rows) = values.transpose();
  }
  return h;
}

std::string saveToString(const Graph& graph) {
  std::ostringstream out;
  saveGraph(graph, out);
  return out.str();
}

Graph loadFromString(const std::string& text, const std::string& sourceName) {
  registerEdgeTypes();
  registerConstraintTypes();
  std::istringstream in(text);
  return loadGraph(in, sourceName);
}

}  // namespace lrsvo::test
