#include "lrsvo/graph/marginal_covariance.h"

#include <memory>
#include <string>
#include <vector>

#include "lrsvo/graph/block_system.h"
#include "lrsvo/graph/dense_backend.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/schur_solver.h"

namespace lrsvo {
namespace {

// The graph's information H at the current estimates, held coordinates
// conditioned on, and where the requested vertices' coordinates lie in it.
class Information {
 public:
  Information(Graph& graph, const std::vector<const Vertex*>& vertices, const std::vector<HeldCoordinate>& held,
              int threads)
      : threads_(checkedThreads(threads)), system_(graph, true), solver_(std::make_unique<DenseBackend>()) {
    for (const Vertex* vertex : vertices) {
      const int block = system_.blockOf(vertex);
      if (block < 0 || block >= system_.freeCount())
        throw Error("covariance: vertex " + std::to_string(vertex->id()) +
                    " is fixed, marginalised or on no edge; expected a free vertex");
      for (int d = 0; d < system_.dim(block); ++d) coordinates_.push_back(system_.offset(block) + d);
    }
    system_.fill(threads);
    for (const HeldCoordinate& h : held) {
      const int block = system_.blockOf(h.vertex);
      if (block >= 0) system_.holdCoordinate(block, h.coordinate);
    }
    solver_.analyze(system_);
  }

  int size() const { return static_cast<int>(coordinates_.size()); }

  // H^-1 r at the requested coordinates, for r zero but at them (`r`, in their
  // order). On the free blocks H x = r is M x = r, M = U - W V^-1 W^T: one
  // Schur solve.
  Eigen::VectorXd solve(const Eigen::VectorXd& r) {
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(system_.scalarCount()), x;
    for (int i = 0; i < size(); ++i) rhs[coordinates_[i]] = r[i];
    if (!solver_.solve(system_, rhs, x, threads_))
      throw Error("covariance: the information of the free vertices is singular (an unfixed gauge?)");
    Eigen::VectorXd atCoordinates(size());
    for (int i = 0; i < size(); ++i) atCoordinates[i] = x[coordinates_[i]];
    return atCoordinates;
  }

 private:
  // Checked before the block system is built from the graph.
  static int checkedThreads(int threads) {
    if (threads < 1) throw Error("covariance: threads must be at least 1, got " + std::to_string(threads));
    return threads;
  }

  int threads_;
  BlockSystem system_;
  SchurSolver solver_;
  std::vector<int> coordinates_;  // scalar indices in H
};

}  // namespace

Eigen::MatrixXd marginalCovariance(Graph& graph, const std::vector<const Vertex*>& vertices,
                                   const std::vector<HeldCoordinate>& held, int threads) {
  Information information(graph, vertices, held, threads);
  const int n = information.size();
  Eigen::MatrixXd covariance(n, n);
  for (int c = 0; c < n; ++c) covariance.col(c) = information.solve(Eigen::VectorXd::Unit(n, c));
  return covariance;
}

double marginalVariance(Graph& graph, const std::vector<const Vertex*>& vertices, const Eigen::VectorXd& coefficients,
                        const std::vector<HeldCoordinate>& held, int threads) {
  Information information(graph, vertices, held, threads);
  if (coefficients.size() != information.size())
    throw Error("covariance: " + std::to_string(coefficients.size()) + " coefficients for " +
                std::to_string(information.size()) + " coordinates");
  return coefficients.dot(information.solve(coefficients));
}

}  // namespace lrsvo
