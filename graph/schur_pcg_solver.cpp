#include "lrsvo/graph/schur_pcg_solver.h"

#include "lrsvo/graph/stopwatch.h"

namespace lrsvo {

bool SchurPcgSolver::solve(const BlockSystem& system, const Eigen::VectorXd& rhs, Eigen::VectorXd& x, int threads) {
  Stopwatch phase;
  lastIterations_ = 0;
  if (!schur_.prepare(system, rhs, threads) || !schur_.invertDiagonalBlocks(system, /*withCouplings=*/true, threads))
    return false;
  const Eigen::VectorXd& b = schur_.reducedRhs();
  const double prepareSeconds = phase.lap();

  // Preconditioned conjugate gradients from xa = 0; r = b - S xa throughout.
  Eigen::VectorXd xa = Eigen::VectorXd::Zero(b.size()), r = b, z, p, q;
  const double bNorm = b.norm();
  if (bNorm > 0.0) {
    schur_.applyDiagonalInverse(system, r, z);
    p = z;
    double rz = r.dot(z), model = 0.0;
    for (int i = 1; i <= options_.maxIterations; ++i) {
      schur_.multiply(system, p, q, threads);
      const double curvature = p.dot(q);
      if (!(curvature > 0.0)) return false;  // S is not positive definite
      const double alpha = rz / curvature;
      xa += alpha * p;
      r -= alpha * q;
      lastIterations_ = i;
      // q(xa) = xa^T (S xa) / 2 - b^T xa with S xa = b - r.
      const double newModel = -0.5 * xa.dot(b + r);
      if (r.norm() <= options_.residualTolerance * bNorm) break;
      if (options_.eta > 0.0 && i * (newModel - model) / newModel < options_.eta) break;
      model = newModel;
      schur_.applyDiagonalInverse(system, r, z);
      const double rzNext = r.dot(z);
      p = z + (rzNext / rz) * p;
      rz = rzNext;
    }
  }
  const double iterateSeconds = phase.lap();

  const bool finite = schur_.backSubstitute(system, rhs, xa, x, threads);
  times_.schurSeconds += prepareSeconds + phase.seconds();
  times_.factorizeSeconds += iterateSeconds;
  return finite;
}

}  // namespace lrsvo
