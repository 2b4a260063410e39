#pragma once

#include "lrsvo/graph/implicit_schur_complement.h"
#include "lrsvo/graph/linear_solver.h"

namespace lrsvo {

struct PowerSeriesOptions {
  // Stops adding terms once the rest of the series, estimated from the last
  // ratio q = |t_k| / |t_k-1| as q / (1 - q) |t_k|, is below tolerance |xa|;
  // 0 sums all maxTerms terms.
  double tolerance = 0.01;
  int maxTerms = 200;
};

// "schur_power_series": eliminates the marginalised vertices like the Schur
// solvers and solves S xa = b by the power series of S^-1 (power bundle
// adjustment). With D the block diagonal of U and S = D (I - T),
// T = D^-1 W V^-1 W^T,
//
//   S^-1 = (I + T + T^2 + ...) D^-1,  xa = t_0 + t_1 + ...,
//   t_0 = D^-1 b,  t_{k+1} = T t_k = t_k - D^-1 S t_k,
//
// one product with the implicit S per term. The series converges when H is
// positive definite and the free vertices are coupled only through
// marginalised ones (U block diagonal, as in bundle adjustment): T's
// eigenvalues then lie in [0, 1). analyze() refuses any other structure. Its
// steps are inexact, to the options' tolerance.
class SchurPowerSeriesSolver : public LinearSolver {
 public:
  explicit SchurPowerSeriesSolver(PowerSeriesOptions options = {}) : options_(options) {}
  bool usesSchurOrdering() const override { return true; }
  bool exactSteps() const override { return false; }
  // Throws lrsvo::Error when an edge joins two free vertices.
  void analyze(const BlockSystem& system) override;
  bool solve(const BlockSystem& system, const Eigen::VectorXd& rhs, Eigen::VectorXd& x, int threads) override;

  // Terms summed in the last solve.
  int lastTerms() const { return lastTerms_; }

 private:
  PowerSeriesOptions options_;
  ImplicitSchurComplement schur_;
  int lastTerms_ = 0;
};

}  // namespace lrsvo
