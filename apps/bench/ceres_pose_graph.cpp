#include "apps/bench/ceres_pose_graph.h"

#include <cmath>
#include <map>
#include <numbers>
#include <vector>

#include <ceres/autodiff_cost_function.h>
#include <ceres/manifold.h>
#include <ceres/problem.h>
#include <ceres/solver.h>
#include <ceres/version.h>
#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include "apps/bench/ceres_solve.h"
#include "lrsvo/edges/edge_se2.h"
#include "lrsvo/edges/edge_se3_quat.h"
#include "lrsvo/graph/error.h"

namespace lrsvo::bench {

namespace {

// The angle in [-pi, pi): ours wraps into (-pi, pi], the same but on a set of measure zero.
template <typename T>
T wrapped(const T& angle) {
  using std::floor;
  const double period = 2.0 * std::numbers::pi;
  return angle - period * floor((angle + std::numbers::pi) / period);
}

// The upper Cholesky factor U of the information (U^T U = Omega), as BaseEdge whitens.
template <int N>
Eigen::Matrix<double, N, N> whitening(const Eigen::Matrix<double, N, N>& information) {
  return Eigen::LLT<Eigen::Matrix<double, N, N>>(information).matrixU();
}

// EdgeSE2's residual: r_t = Rz^T (Ri^T (t_j - t_i) - t_z), r_theta = wrap(theta_j - theta_i - theta_z), whitened.
class RelativePoseSE2Residual {
 public:
  RelativePoseSE2Residual(const Eigen::Vector3d& measurement, const Eigen::Matrix3d& information)
      : measurement_(measurement), whitening_(whitening(information)) {}

  template <typename T>
  bool operator()(const T* from, const T* to, T* residual) const {
    using std::cos;
    using std::sin;
    const T c = cos(from[2]), s = sin(from[2]);
    const T dx = to[0] - from[0], dy = to[1] - from[1];
    const T u = c * dx + s * dy - measurement_[0];
    const T v = -s * dx + c * dy - measurement_[1];
    const double cz = std::cos(measurement_[2]), sz = std::sin(measurement_[2]);
    Eigen::Matrix<T, 3, 1> r;
    r << cz * u + sz * v, -sz * u + cz * v, wrapped(to[2] - from[2] - measurement_[2]);
    Eigen::Map<Eigen::Matrix<T, 3, 1>>{residual} = whitening_.cast<T>() * r;
    return true;
  }

  static ceres::CostFunction* create(const EdgeSE2& edge) {
    return new ceres::AutoDiffCostFunction<RelativePoseSE2Residual, 3, 3, 3>(
        new RelativePoseSE2Residual(edge.measurement(), edge.information()));
  }

 private:
  Eigen::Vector3d measurement_;
  Eigen::Matrix3d whitening_;
};

// EdgeSE3Quat's residual: translation and quaternion vector part (w >= 0) of Z^-1 X_i^-1 X_j, whitened.
class RelativePoseSE3Residual {
 public:
  explicit RelativePoseSE3Residual(const EdgeSE3Quat& edge)
      : inverseRotation_(edge.relativeQuaternion().normalized().conjugate()),
        translation_(edge.relativeTranslation()),
        whitening_(whitening(edge.information())) {}

  template <typename T>
  bool operator()(const T* fromTranslation, const T* fromRotation, const T* toTranslation, const T* toRotation,
                  T* residual) const {
    const Eigen::Map<const Eigen::Matrix<T, 3, 1>> ti(fromTranslation), tj(toTranslation);
    const Eigen::Map<const Eigen::Quaternion<T>> qi(fromRotation), qj(toRotation);
    const Eigen::Quaternion<T> zInverse = inverseRotation_.cast<T>();
    Eigen::Quaternion<T> q = zInverse * qi.conjugate() * qj;
    if (q.w() < T(0.0)) q.coeffs() = -q.coeffs();
    Eigen::Matrix<T, 6, 1> r;
    r << zInverse * (qi.conjugate() * (tj - ti) - translation_.cast<T>()), q.vec();
    Eigen::Map<Eigen::Matrix<T, 6, 1>>{residual} = whitening_.cast<T>() * r;
    return true;
  }

  static ceres::CostFunction* create(const EdgeSE3Quat& edge) {
    return new ceres::AutoDiffCostFunction<RelativePoseSE3Residual, 6, 3, 4, 3, 4>(new RelativePoseSE3Residual(edge));
  }

 private:
  Eigen::Quaterniond inverseRotation_;
  Eigen::Vector3d translation_;
  Eigen::Matrix<double, 6, 6> whitening_;
};

// Ceres' copy of one vertex: SE2 (x, y, theta) in `values`, SE3 translation then x y z w.
struct Block {
  Vertex* vertex = nullptr;
  std::vector<double> values;
};

}  // namespace

SolveResult solvePoseGraphWithCeres(Graph& graph, const SolverOptions& stopping) {
  std::map<const Vertex*, Block> blocks;
  ceres::Problem::Options problemOptions;
  problemOptions.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problemOptions);
  ceres::EigenQuaternionManifold quaternionManifold;
  for (const auto& vertex : graph.vertices()) {
    Block& block = blocks[vertex.get()];
    block.vertex = vertex.get();
    if (const auto* planar = dynamic_cast<const VertexSE2*>(vertex.get())) {
      block.values.assign(planar->pose().data(), planar->pose().data() + 3);
      problem.AddParameterBlock(block.values.data(), 3);
    } else if (const auto* spatial = dynamic_cast<const VertexSE3Quat*>(vertex.get())) {
      block.values.assign(spatial->translation().data(), spatial->translation().data() + 3);
      const Eigen::Quaterniond& q = spatial->unitQuaternion();
      block.values.insert(block.values.end(), q.coeffs().data(), q.coeffs().data() + 4);
      problem.AddParameterBlock(block.values.data(), 3);
      problem.AddParameterBlock(block.values.data() + 3, 4, &quaternionManifold);
    } else {
      throw Error(std::string("bench graph: Ceres has no model of vertex type ") + vertex->typeTag());
    }
  }
  for (const auto& edge : graph.edges()) {
    double* from = blocks.at(edge->vertex(0)).values.data();
    double* to = blocks.at(edge->vertex(1)).values.data();
    if (const auto* planar = dynamic_cast<const EdgeSE2*>(edge.get()))
      problem.AddResidualBlock(RelativePoseSE2Residual::create(*planar), nullptr, from, to);
    else if (const auto* spatial = dynamic_cast<const EdgeSE3Quat*>(edge.get()))
      problem.AddResidualBlock(RelativePoseSE3Residual::create(*spatial), nullptr, from, from + 3, to, to + 3);
    else
      throw Error(std::string("bench graph: Ceres has no model of edge type ") + edge->typeTag());
  }
  for (const auto& [vertex, block] : blocks) {
    if (!vertex->fixed()) continue;
    problem.SetParameterBlockConstant(block.values.data());
    if (block.values.size() == 7) problem.SetParameterBlockConstant(block.values.data() + 3);
  }

  const SolveResult result = solveWithCeres(ceresSolverOptions(stopping, ceres::SPARSE_NORMAL_CHOLESKY), problem);
  for (auto& [vertex, block] : blocks) block.vertex->setEstimate(block.values.data());
  return result;
}

std::string ceresPoseGraphConfiguration() {
  return std::string("Ceres ") + CERES_VERSION_STRING +
         ": AutoDiff Jacobians of the same residuals (edges/edge_se2.cpp, edges/edge_se3_quat.cpp), SE3 rotations on "
         "EigenQuaternionManifold, LEVENBERG_MARQUARDT, jacobi_scaling on, SPARSE_NORMAL_CHOLESKY on SUITE_SPARSE";
}

}  // namespace lrsvo::bench
