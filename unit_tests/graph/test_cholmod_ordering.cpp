// The CHOLMOD back end's choices: the ordering (nested dissection of the block
// graph where the factor fills in heavily, as in the lattices of pose graphs,
// never where it does not, and the same solution whichever ordering is kept),
// the factorisation's kind (simplicial where supernodes are small, supernodal
// otherwise, both solving the system and both reporting a matrix that is not
// positive definite), and the same solution for any thread count.
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "lrsvo/graph/cholmod_backend.h"

namespace lrsvo::test {
namespace {

struct BlockPattern {
  std::vector<int> dims;
  std::vector<std::pair<int, int>> pairs;  // (row, col), row <= col, diagonals included
};

// A side x side lattice of blocks, each coupled to its right and lower
// neighbours: the structure of a planar pose graph.
BlockPattern lattice(int side, int dim = 6) {
  BlockPattern pattern;
  pattern.dims.assign(side * side, dim);
  for (int r = 0; r < side; ++r)
    for (int c = 0; c < side; ++c) {
      const int i = r * side + c;
      pattern.pairs.emplace_back(i, i);
      if (c + 1 < side) pattern.pairs.emplace_back(i, i + 1);
      if (r + 1 < side) pattern.pairs.emplace_back(i, i + side);
    }
  return pattern;
}

// Every block coupled to every other: no fill for any ordering to save.
BlockPattern dense(int blocks) {
  BlockPattern pattern;
  pattern.dims.assign(blocks, 6);
  for (int i = 0; i < blocks; ++i)
    for (int j = i; j < blocks; ++j) pattern.pairs.emplace_back(i, j);
  return pattern;
}

struct FilledSystem {
  Eigen::SparseMatrix<double> matrix;  // the whole symmetric matrix, as the blocks hold its upper triangle
  Eigen::VectorXd rhs;
};

// Fills the blocks with a symmetric matrix with `diagonal` I on its diagonal
// and off-diagonal entries within +-0.1 (strictly diagonally dominant for a
// diagonal of 10: at most 4 * 6 of them per row in the lattice), and draws a
// seeded right-hand side.
FilledSystem fill(CholmodBackend& backend, const BlockPattern& pattern, double diagonal = 10.0) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> offDiagonal(-0.1, 0.1);
  std::vector<int> offsets{0};
  for (int d : pattern.dims) offsets.push_back(offsets.back() + d);
  FilledSystem system{Eigen::SparseMatrix<double>(offsets.back(), offsets.back()), Eigen::VectorXd(offsets.back())};
  std::vector<Eigen::Triplet<double>> entries;
  backend.setZero();
  for (int k = 0; k < static_cast<int>(pattern.pairs.size()); ++k) {
    const auto [row, col] = pattern.pairs[k];
    const SymmetricBackend::BlockRef block = backend.block(k);
    for (int c = 0; c < pattern.dims[col]; ++c)
      for (int r = 0; r < pattern.dims[row]; ++r) {
        const double value = row == col ? (r == c ? diagonal : 0.0) : offDiagonal(random);
        block.data[c * block.ld + r] = value;
        entries.emplace_back(offsets[row] + r, offsets[col] + c, value);
        if (row != col) entries.emplace_back(offsets[col] + c, offsets[row] + r, value);
      }
  }
  system.matrix.setFromTriplets(entries.begin(), entries.end());
  for (int i = 0; i < system.rhs.size(); ++i) system.rhs[i] = offDiagonal(random);
  return system;
}

Eigen::VectorXd fillAndSolve(CholmodBackend& backend, const BlockPattern& pattern) {
  const FilledSystem system = fill(backend, pattern);
  Eigen::VectorXd x;
  EXPECT_TRUE(backend.solve(system.rhs, x, 1));
  return x;
}

TEST(CholmodOrdering, HeavyFillTakesTheOrderingWithFewerFlops) {
  const BlockPattern pattern = lattice(60);
  CholmodBackend amd(CholmodOrdering::kAmd), leastWork(CholmodOrdering::kLeastWork);
  amd.analyze(pattern.dims, pattern.pairs);
  leastWork.analyze(pattern.dims, pattern.pairs);
  EXPECT_STREQ(amd.orderingName(), "amd");
  const std::string dissection = leastWork.orderingName();
  EXPECT_TRUE(dissection == "metis" || dissection == "nesdis") << dissection;
  EXPECT_LT(leastWork.factorizationFlops(), amd.factorizationFlops());

  // A condition number below (10 + 2.4) / (10 - 2.4): both orderings give the
  // same solution to within a few units of rounding.
  const Eigen::VectorXd xAmd = fillAndSolve(amd, pattern);
  const Eigen::VectorXd xLeastWork = fillAndSolve(leastWork, pattern);
  EXPECT_LE((xLeastWork - xAmd).norm(), 1e-13 * xAmd.norm());
}

TEST(CholmodOrdering, NoFillKeepsAmdWithoutTryingMetis) {
  const BlockPattern pattern = dense(12);
  CholmodBackend leastWork;
  leastWork.analyze(pattern.dims, pattern.pairs);
  EXPECT_STREQ(leastWork.orderingName(), "amd");
}

// An SE(2) pose graph's lattice of 3 x 3 blocks: supernodes of a few blocks,
// factorised simplicially. A dense system of 120 unknowns: one supernode of
// 120^3 / 3 = 5.8e5 flops, supernodal.
TEST(CholmodFactorization, SmallSupernodesAreFactorisedSimplicially) {
  const BlockPattern planar = lattice(30, 3), full = dense(20);
  CholmodBackend planarBackend, fullBackend;
  planarBackend.analyze(planar.dims, planar.pairs);
  fullBackend.analyze(full.dims, full.pairs);
  EXPECT_FALSE(planarBackend.supernodal());
  EXPECT_TRUE(fullBackend.supernodal());
}

// Cholesky is backward stable: the residual is within c n eps |A| |x|, c a
// small constant; the check allows c = 1 over the largest dimension here.
TEST(CholmodFactorization, EitherKindSolvesTheSystem) {
  for (const BlockPattern& pattern : {lattice(30, 3), dense(20)}) {
    CholmodBackend backend;
    backend.analyze(pattern.dims, pattern.pairs);
    const FilledSystem system = fill(backend, pattern);
    Eigen::VectorXd x;
    ASSERT_TRUE(backend.solve(system.rhs, x, 1)) << (backend.supernodal() ? "supernodal" : "simplicial");
    const double n = static_cast<double>(system.rhs.size());
    const double bound = n * std::numeric_limits<double>::epsilon() * system.matrix.norm() * x.norm();
    EXPECT_LE((system.matrix * x - system.rhs).norm(), bound) << (backend.supernodal() ? "supernodal" : "simplicial");
  }
}

// A diagonal of -1 makes the matrix indefinite: either kind reports it.
TEST(CholmodFactorization, EitherKindReportsAMatrixThatIsNotPositiveDefinite) {
  for (const BlockPattern& pattern : {lattice(30, 3), dense(20)}) {
    CholmodBackend backend;
    backend.analyze(pattern.dims, pattern.pairs);
    const FilledSystem system = fill(backend, pattern, -1.0);
    Eigen::VectorXd x;
    EXPECT_FALSE(backend.solve(system.rhs, x, 1)) << (backend.supernodal() ? "supernodal" : "simplicial");
  }
}

// CHOLMOD's supernodal factorisation runs its large supernodes' updates in
// OpenMP regions; the thread count the solve is given must not change the
// solution beyond rounding (the bound of EitherKindSolvesTheSystem).
TEST(CholmodFactorization, ThreadCountKeepsTheSolution) {
  const BlockPattern pattern = dense(60);
  CholmodBackend backend;
  backend.analyze(pattern.dims, pattern.pairs);
  ASSERT_TRUE(backend.supernodal());
  Eigen::VectorXd reference;
  for (const int threads : {1, 2, 4}) {
    const FilledSystem system = fill(backend, pattern);
    Eigen::VectorXd x;
    ASSERT_TRUE(backend.solve(system.rhs, x, threads)) << threads << " threads";
    if (threads == 1) reference = x;
    const double n = static_cast<double>(system.rhs.size());
    const double bound = n * std::numeric_limits<double>::epsilon() * system.matrix.norm() * x.norm();
    EXPECT_LE((system.matrix * x - system.rhs).norm(), bound) << threads << " threads";
    EXPECT_LE((x - reference).norm(), 2.0 * bound) << threads << " threads";
  }
}

}  // namespace
}  // namespace lrsvo::test
