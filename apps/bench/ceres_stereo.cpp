#include "apps/bench/ceres_stereo.h"

#include <memory>
#include <string>
#include <utility>

#include <ceres/autodiff_cost_function.h>
#include <ceres/loss_function.h>
#include <ceres/manifold.h>
#include <ceres/ordered_groups.h>
#include <ceres/product_manifold.h>
#include <ceres/rotation.h>
#include <Eigen/Cholesky>

#include "apps/bench/ceres_solve.h"
#include "lrsvo/edges/edge_project_base.h"
#include "lrsvo/edges/edge_project_secondary.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/robust_kernel.h"
#include "lrsvo/vertices/vertex_point3.h"
#include "lrsvo/vertices/vertex_pose.h"
#include "lrsvo/vertices/vertex_scale.h"
#include "lrsvo/vertices/vertex_stereo_extrinsic.h"

namespace lrsvo::bench {

namespace {

using PoseManifold = ceres::ProductManifold<ceres::EuclideanManifold<3>, ceres::EigenQuaternionManifold>;

// One pixel measurement: residual = U (pi(K p) - z), with U^T U the edge's information.
class Observation {
 public:
  template <typename EdgeType>
  explicit Observation(const EdgeType& edge, const PinholeIntrinsics& intrinsics)
      : intrinsics_(intrinsics),
        measurement_(edge.measurement()),
        sqrtInformation_(Eigen::LLT<Eigen::Matrix2d>(edge.information()).matrixU()) {}

  template <typename T>
  void residual(const T* inCamera, T* residual) const {
    const T du = intrinsics_.fx * inCamera[0] / inCamera[2] + intrinsics_.cx - measurement_.x();
    const T dv = intrinsics_.fy * inCamera[1] / inCamera[2] + intrinsics_.cy - measurement_.y();
    residual[0] = sqrtInformation_(0, 0) * du + sqrtInformation_(0, 1) * dv;
    residual[1] = sqrtInformation_(1, 1) * dv;
  }

 private:
  PinholeIntrinsics intrinsics_;
  Eigen::Vector2d measurement_;
  Eigen::Matrix2d sqrtInformation_;  // upper triangular
};

// X_c0 = R X + t; pose = (t, unit quaternion x y z w).
template <typename T>
void pointInBase(const T* pose, const T* point, T* inBase) {
  const T quaternion[4] = {pose[6], pose[3], pose[4], pose[5]};  // Ceres' w x y z order
  ceres::UnitQuaternionRotatePoint(quaternion, point, inBase);
  for (int i = 0; i < 3; ++i) inBase[i] += pose[i];
}

// X_c1 = R_s (X_c0 - c / kappa), R_s = Rz(yaw) Ry(pitch) Rx(roll), s = (c, roll, pitch, yaw).
template <typename T>
void pointInSecondary(const T* inBase, const T* s, const T& kappa, T* inSecondary) {
  using std::cos;
  using std::sin;
  const T x = inBase[0] - s[0] / kappa, y = inBase[1] - s[1] / kappa, z = inBase[2] - s[2] / kappa;
  const T cr = cos(s[3]), sr = sin(s[3]), cp = cos(s[4]), sp = sin(s[4]), cy = cos(s[5]), sy = sin(s[5]);
  const T y1 = cr * y - sr * z, z1 = sr * y + cr * z;     // Rx(roll)
  const T x2 = cp * x + sp * z1, z2 = -sp * x + cp * z1;  // Ry(pitch)
  inSecondary[0] = cy * x2 - sy * y1;                     // Rz(yaw)
  inSecondary[1] = sy * x2 + cy * y1;
  inSecondary[2] = z2;
}

class BaseResidual {
 public:
  explicit BaseResidual(Observation observation) : observation_(std::move(observation)) {}
  template <typename T>
  bool operator()(const T* pose, const T* point, T* residual) const {
    T inBase[3];
    pointInBase(pose, point, inBase);
    observation_.residual(inBase, residual);
    return true;
  }

 private:
  Observation observation_;
};

class SecondaryResidual {
 public:
  explicit SecondaryResidual(Observation observation) : observation_(std::move(observation)) {}
  template <typename T>
  bool operator()(const T* pose, const T* point, const T* extrinsic, T* residual) const {
    T inBase[3], inSecondary[3];
    pointInBase(pose, point, inBase);
    pointInSecondary(inBase, extrinsic, T(1.0), inSecondary);
    observation_.residual(inSecondary, residual);
    return true;
  }

 private:
  Observation observation_;
};

class SecondaryScaledResidual {
 public:
  explicit SecondaryScaledResidual(Observation observation) : observation_(std::move(observation)) {}
  template <typename T>
  bool operator()(const T* pose, const T* point, const T* extrinsic, const T* kappa, T* residual) const {
    if (!(kappa[0] > 0.0)) return false;  // ours gives a NaN residual there; Ceres rejects the step alike
    T inBase[3], inSecondary[3];
    pointInBase(pose, point, inBase);
    pointInSecondary(inBase, extrinsic, kappa[0], inSecondary);
    observation_.residual(inSecondary, residual);
    return true;
  }

 private:
  Observation observation_;
};

// The Ceres loss with our kernel's rho (nullptr: plain least squares).
ceres::LossFunction* lossFor(const RobustKernel* kernel) {
  if (!kernel) return nullptr;
  const std::string name = kernel->name();
  if (name == "Huber") return new ceres::HuberLoss(kernel->delta());
  if (name == "Cauchy") return new ceres::CauchyLoss(kernel->delta());
  if (name == "Tukey") return new ceres::TukeyLoss(kernel->delta());
  throw Error("Ceres model: no Ceres loss for the robust kernel '" + name + "'");
}

}  // namespace

CeresStereoModel::CeresStereoModel(const Graph& graph, const Bounds& bounds) {
  blocks_.reserve(graph.vertices().size());
  for (const auto& edge : graph.edges()) addEdge(*edge);

  for (Block& entry : blocks_) {
    if (entry.pose) problem_.SetManifold(entry.values.data(), new PoseManifold());
    if (entry.fixed) problem_.SetParameterBlockConstant(entry.values.data());
  }
  for (const Bounds::Bound& bound : bounds.all()) {
    if (graph.vertex(bound.vertex->id()) != bound.vertex)
      throw Error("Ceres model: a bound names vertex " + std::to_string(bound.vertex->id()) +
                  ", which is not in the graph");
    const auto found = blockIndex_.find(bound.vertex);
    if (found == blockIndex_.end()) continue;  // in no edge: Ceres never moves it
    double* values = blocks_[found->second].values.data();
    problem_.SetParameterLowerBound(values, bound.index, bound.lower);
    problem_.SetParameterUpperBound(values, bound.index, bound.upper);
  }
}

double* CeresStereoModel::block(const Vertex* vertex) {
  const auto [entry, inserted] = blockIndex_.emplace(vertex, static_cast<int>(blocks_.size()));
  if (inserted) {
    const bool pose = dynamic_cast<const VertexPose*>(vertex) != nullptr;
    Block added{vertex->id(), vertex->fixed(), vertex->marginalized(), pose,
                std::vector<double>(vertex->estimateSize())};
    vertex->getEstimate(added.values.data());
    if (pose) {
      // Unit length, as the manifold keeps it and as our rotation matrix is built.
      Eigen::Map<Eigen::Vector4d> quaternion(added.values.data() + 3);
      quaternion.normalize();
    }
    blocks_.push_back(std::move(added));
  }
  return blocks_[entry->second].values.data();
}

void CeresStereoModel::addEdge(const Edge& edge) {
  // Each modelled edge accepts only the vertex types modelled here.
  std::vector<double*> blocks;
  for (const Vertex* vertex : edge.vertices()) blocks.push_back(block(vertex));
  if (const auto* base = dynamic_cast<const EdgeProjectBase*>(&edge)) {
    std::unique_ptr<ceres::LossFunction> loss(lossFor(base->robustKernel().get()));
    problem_.AddResidualBlock(new ceres::AutoDiffCostFunction<BaseResidual, 2, 7, 3>(
                                  new BaseResidual(Observation(*base, base->intrinsics()))),
                              loss.release(), blocks[0], blocks[1]);
  } else if (const auto* secondary = dynamic_cast<const EdgeProjectSecondary*>(&edge)) {
    std::unique_ptr<ceres::LossFunction> loss(lossFor(secondary->robustKernel().get()));
    problem_.AddResidualBlock(new ceres::AutoDiffCostFunction<SecondaryResidual, 2, 7, 3, 6>(
                                  new SecondaryResidual(Observation(*secondary, secondary->camera().intrinsics))),
                              loss.release(), blocks[0], blocks[1], blocks[2]);
  } else if (const auto* scaled = dynamic_cast<const EdgeProjectSecondaryScaled*>(&edge)) {
    std::unique_ptr<ceres::LossFunction> loss(lossFor(scaled->robustKernel().get()));
    problem_.AddResidualBlock(new ceres::AutoDiffCostFunction<SecondaryScaledResidual, 2, 7, 3, 6, 1>(
                                  new SecondaryScaledResidual(Observation(*scaled, scaled->camera().intrinsics))),
                              loss.release(), blocks[0], blocks[1], blocks[2], blocks[3]);
  } else {
    throw Error(std::string("Ceres model: edge type ") + edge.typeTag() + " is not modelled");
  }
}

double CeresStereoModel::cost() {
  double cost = 0.0;
  problem_.Evaluate(ceres::Problem::EvaluateOptions(), &cost, nullptr, nullptr, nullptr);
  return cost;
}

SolveResult CeresStereoModel::solve(const SolverOptions& stopping, ceres::LinearSolverType linearSolver) {
  ceres::Solver::Options options = ceresSolverOptions(stopping, linearSolver);
  auto ordering = std::make_shared<ceres::ParameterBlockOrdering>();
  for (Block& entry : blocks_) ordering->AddElementToGroup(entry.values.data(), entry.marginalized ? 0 : 1);
  options.linear_solver_ordering = ordering;
  return solveWithCeres(options, problem_);
}

void CeresStereoModel::copyTo(Graph& graph) const {
  for (const Block& entry : blocks_) {
    Vertex* vertex = graph.vertex(entry.vertexId);
    if (!vertex || vertex->estimateSize() != static_cast<int>(entry.values.size()))
      throw Error("Ceres model: the graph has no vertex " + std::to_string(entry.vertexId) + " of the model's type");
    vertex->setEstimate(entry.values.data());
  }
}

}  // namespace lrsvo::bench
