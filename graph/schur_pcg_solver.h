#pragma once

#include "lrsvo/graph/implicit_schur_complement.h"
#include "lrsvo/graph/linear_solver.h"

namespace lrsvo {

struct ConjugateGradientOptions {
  // Stops at iteration i once the reduced quadratic model
  // q(x) = x^T S x / 2 - b^T x falls too little: i (q_i - q_{i-1}) / q_i < eta
  // (Nash and Sofer's rule for truncated Newton steps, Ceres' eta); 0 turns it off.
  double eta = 0.1;
  // Stops once |b - S x| <= residualTolerance |b|; 0 turns it off.
  double residualTolerance = 0.0;
  int maxIterations = 500;
};

// "schur_pcg": eliminates the marginalised vertices like the Schur solvers,
// but solves S xa = b by conjugate gradients on the implicit S (never formed,
// see implicit_schur_complement.h), preconditioned by S's diagonal blocks
// (Schur-Jacobi). Each iteration costs one product with S, two passes over
// the couplings; memory stays that of H. Its steps are inexact, to the
// options' tolerances.
class SchurPcgSolver : public LinearSolver {
 public:
  explicit SchurPcgSolver(ConjugateGradientOptions options = {}) : options_(options) {}
  bool usesSchurOrdering() const override { return true; }
  bool exactSteps() const override { return false; }
  void analyze(const BlockSystem& system) override { schur_.analyze(system); }
  bool solve(const BlockSystem& system, const Eigen::VectorXd& rhs, Eigen::VectorXd& x, int threads) override;

  // Conjugate-gradient iterations of the last solve.
  int lastIterations() const { return lastIterations_; }

 private:
  ConjugateGradientOptions options_;
  ImplicitSchurComplement schur_;
  int lastIterations_ = 0;
};

}  // namespace lrsvo
