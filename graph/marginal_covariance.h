#pragma once

#include <vector>

#include <Eigen/Core>

#include "lrsvo/graph/graph.h"

namespace lrsvo {

// One scalar parameter of a vertex (coordinate of its update).
struct HeldCoordinate {
  const Vertex* vertex;
  int coordinate;
};

// The joint covariance of free vertices' updates at the current estimates,
// in the order given: the corresponding blocks of the inverse Gauss-Newton
// information of the whole graph, marginalised vertices (points) eliminated
// by the Schur complement (SchurSolver, one solve per requested coordinate,
// on up to `threads` threads; the result is the same for any count).
// Held coordinates are conditioned on (treated as known): directions that
// only a bound or a gauge determines would otherwise make the information
// singular. The reduced system of the non-marginalised vertices is formed
// densely, so this suits windows, not large batches. Throws lrsvo::Error
// when a vertex is fixed, marginalised or not on an edge, or when the
// information is not positive definite.
Eigen::MatrixXd marginalCovariance(Graph& graph, const std::vector<const Vertex*>& vertices,
                                   const std::vector<HeldCoordinate>& held = {}, int threads = 1);

// The variance c^T Sigma c of one linear combination of the same updates,
// c holding a coefficient per coordinate of the vertices in the order given
// (Sigma: marginalCovariance's result), by a single Schur solve. Throws as
// marginalCovariance does, and when c has another length.
double marginalVariance(Graph& graph, const std::vector<const Vertex*>& vertices, const Eigen::VectorXd& coefficients,
                        const std::vector<HeldCoordinate>& held = {}, int threads = 1);

}  // namespace lrsvo
