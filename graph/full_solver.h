#pragma once

#include <memory>

#include "lrsvo/graph/linear_solver.h"
#include "lrsvo/graph/symmetric_backend.h"

namespace lrsvo {

// Solves the whole system H x = rhs with one backend; marginalised vertices
// are treated like any other.
class FullSolver : public LinearSolver {
 public:
  explicit FullSolver(std::unique_ptr<SymmetricBackend> backend) : backend_(std::move(backend)) {}
  bool usesSchurOrdering() const override { return false; }
  void analyze(const BlockSystem& system) override;
  bool solve(const BlockSystem& system, const Eigen::VectorXd& rhs, Eigen::VectorXd& x, int threads) override;
  FactorizationInfo factorization() const override { return backend_->factorization(); }

 private:
  std::unique_ptr<SymmetricBackend> backend_;
};

}  // namespace lrsvo
