#include "lrsvo/graph/schur_power_series_solver.h"

#include <string>

#include "lrsvo/graph/error.h"
#include "lrsvo/graph/stopwatch.h"

namespace lrsvo {

void SchurPowerSeriesSolver::analyze(const BlockSystem& system) {
  for (const auto& block : system.blocks())
    if (block.row != block.col && block.col < system.freeCount())
      throw Error("schur_power_series: an edge joins free vertices " + std::to_string(system.vertex(block.row)->id()) +
                  " and " + std::to_string(system.vertex(block.col)->id()) +
                  "; the series needs free vertices coupled only through marginalised ones (use schur_pcg)");
  schur_.analyze(system);
}

bool SchurPowerSeriesSolver::solve(const BlockSystem& system, const Eigen::VectorXd& rhs, Eigen::VectorXd& x,
                                   int threads) {
  Stopwatch phase;
  lastTerms_ = 0;
  if (!schur_.prepare(system, rhs, threads) || !schur_.invertDiagonalBlocks(system, /*withCouplings=*/false, threads))
    return false;
  const double prepareSeconds = phase.lap();

  Eigen::VectorXd term, xa, product, correction;
  schur_.applyDiagonalInverse(system, schur_.reducedRhs(), term);
  xa = term;
  lastTerms_ = 1;
  double termNorm = term.norm(), previousNorm = 0.0;
  while (lastTerms_ < options_.maxTerms && termNorm > 0.0) {
    // The terms shrink by about q = |t_k| / |t_k-1| each: the rest of the
    // series is then about q / (1 - q) |t_k|.
    const double ratio = previousNorm > 0.0 ? termNorm / previousNorm : 1.0;
    if (ratio < 1.0 && ratio / (1.0 - ratio) * termNorm <= options_.tolerance * xa.norm()) break;
    schur_.multiply(system, term, product, threads);
    schur_.applyDiagonalInverse(system, product, correction);
    term -= correction;
    xa += term;
    ++lastTerms_;
    previousNorm = termNorm;
    termNorm = term.norm();
  }
  const double seriesSeconds = phase.lap();

  const bool finite = schur_.backSubstitute(system, rhs, xa, x, threads);
  times_.schurSeconds += prepareSeconds + phase.seconds();
  times_.factorizeSeconds += seriesSeconds;
  return finite;
}

}  // namespace lrsvo
