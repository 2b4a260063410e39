#include "lrsvo/graph/marginal_covariance.h"

#include <memory>
#include <string>
#include <vector>

#include "lrsvo/graph/block_system.h"
#include "lrsvo/graph/dense_backend.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/schur_solver.h"

namespace lrsvo {

Eigen::MatrixXd marginalCovariance(Graph& graph, const std::vector<const Vertex*>& vertices,
                                   const std::vector<HeldCoordinate>& held, int threads) {
  if (threads < 1) throw Error("covariance: threads must be at least 1, got " + std::to_string(threads));
  BlockSystem system(graph, true);
  std::vector<int> targets;
  int size = 0;
  for (const Vertex* vertex : vertices) {
    const int block = system.blockOf(vertex);
    if (block < 0 || block >= system.freeCount())
      throw Error("covariance: vertex " + std::to_string(vertex->id()) +
                  " is fixed, marginalised or on no edge; expected a free vertex");
    targets.push_back(block);
    size += system.dim(block);
  }
  system.fill(threads);
  for (const HeldCoordinate& h : held) {
    const int block = system.blockOf(h.vertex);
    if (block >= 0) system.holdCoordinate(block, h.coordinate);
  }

  // Column c of H^-1 solves H x = e_c; on the free vertices it is column c of
  // the inverse reduced information S^-1 (S = U - W V^-1 W^T), which the
  // solver's Schur elimination forms.
  SchurSolver solver(std::make_unique<DenseBackend>());
  solver.analyze(system);
  Eigen::MatrixXd covariance(size, size);
  Eigen::VectorXd unit = Eigen::VectorXd::Zero(system.scalarCount()), column;
  for (int t = 0, c = 0; t < static_cast<int>(targets.size()); ++t)
    for (int d = 0; d < system.dim(targets[t]); ++d, ++c) {
      const int coordinate = system.offset(targets[t]) + d;
      unit[coordinate] = 1.0;
      if (!solver.solve(system, unit, column, threads))
        throw Error("covariance: the information of the free vertices is singular (an unfixed gauge?)");
      unit[coordinate] = 0.0;
      for (int s = 0, r = 0; s < static_cast<int>(targets.size()); r += system.dim(targets[s++]))
        covariance.block(r, c, system.dim(targets[s]), 1) =
            column.segment(system.offset(targets[s]), system.dim(targets[s]));
    }
  return covariance;
}

}  // namespace lrsvo
