#include <Eigen/QR>

#include "lrsvo/graph/builtin_plugins.h"
#include "lrsvo/graph/dense_backend.h"
#include "lrsvo/graph/full_solver.h"
#include "lrsvo/graph/registry.h"
#include "lrsvo/graph/stopwatch.h"

namespace lrsvo {
namespace {

// Solves the damped least-squares problem min |J dx + r|^2 + dx^T D dx by
// Householder QR of the Jacobian itself, never forming J^T J, whose condition
// number is that of J squared: on small, ill-conditioned problems (the NIST
// regressions) this keeps twice the digits of a Cholesky step. Columns are
// scaled by 1 / (1 + |J_i|) first (Jacobi scaling), so the factorisation sees
// columns of like size. Where H is not J^T J (cost edges, held coordinates,
// a right-hand side other than -g) it solves H x = rhs by dense Cholesky.
class DenseQrSolver : public LinearSolver {
 public:
  bool usesSchurOrdering() const override { return false; }
  void analyze(const BlockSystem& system) override { cholesky_.analyze(system); }

  bool solve(const BlockSystem& system, const Eigen::VectorXd& rhs, Eigen::VectorXd& x, int threads) override {
    if (!(rhs + system.gradient()).isZero(0.0) || !system.stackJacobian(jacobian_, residual_)) {
      const bool ok = cholesky_.solve(system, rhs, x, threads);
      times_.factorizeSeconds = cholesky_.times().factorizeSeconds + qrSeconds_;
      return ok;
    }
    const Stopwatch start;
    const Eigen::Index m = jacobian_.rows(), n = jacobian_.cols();
    const Eigen::ArrayXd scale = 1.0 / (1.0 + jacobian_.colwise().norm().transpose().array());
    const Eigen::ArrayXd shift = system.diagonalShift().array().max(0.0);
    Eigen::MatrixXd augmented(m + n, n);
    augmented.topRows(m) = jacobian_ * scale.matrix().asDiagonal();
    augmented.bottomRows(n) = (shift.sqrt() * scale).matrix().asDiagonal();
    Eigen::VectorXd target = Eigen::VectorXd::Zero(m + n);
    target.head(m) = -residual_;
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(augmented);
    x = scale.matrix().asDiagonal() * qr.solve(target);
    qrSeconds_ += start.seconds();
    times_.factorizeSeconds = cholesky_.times().factorizeSeconds + qrSeconds_;
    return x.allFinite();
  }

 private:
  FullSolver cholesky_{std::make_unique<DenseBackend>()};
  Eigen::MatrixXd jacobian_;
  Eigen::VectorXd residual_;
  double qrSeconds_ = 0.0;
};

}  // namespace

void addDenseQrSolver(Registry<LinearSolver>& registry) {
  registry.addType<DenseQrSolver>(
      "dense_qr", "dense Householder QR of the Jacobian (Jacobi-scaled), for small ill-conditioned problems");
}

}  // namespace lrsvo
