// The CHOLMOD back end's choice of ordering: METIS where the factor fills in
// heavily (the lattices of pose graphs), never where it does not, and the same
// solution whichever ordering is kept.
#include <random>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Core>

#include "lrsvo/graph/cholmod_backend.h"

namespace lrsvo::test {
namespace {

struct BlockPattern {
  std::vector<int> dims;
  std::vector<std::pair<int, int>> pairs;  // (row, col), row <= col, diagonals included
};

// A side x side lattice of 6-dimensional blocks, each coupled to its right and
// lower neighbours: the structure of a planar pose graph.
BlockPattern lattice(int side) {
  BlockPattern pattern;
  pattern.dims.assign(side * side, 6);
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

// Fills the blocks with a strictly diagonally dominant matrix (10 I on the
// diagonal, off-diagonal entries within +-0.1, at most 4 * 6 of them per row
// in the lattice) and solves with a seeded right-hand side.
Eigen::VectorXd fillAndSolve(CholmodBackend& backend, const BlockPattern& pattern) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> offDiagonal(-0.1, 0.1);
  backend.setZero();
  for (int k = 0; k < static_cast<int>(pattern.pairs.size()); ++k) {
    const auto [row, col] = pattern.pairs[k];
    const SymmetricBackend::BlockRef block = backend.block(k);
    for (int c = 0; c < pattern.dims[col]; ++c)
      for (int r = 0; r < pattern.dims[row]; ++r)
        block.data[c * block.ld + r] = row == col ? (r == c ? 10.0 : 0.0) : offDiagonal(random);
  }
  int size = 0;
  for (int d : pattern.dims) size += d;
  Eigen::VectorXd rhs(size);
  for (int i = 0; i < size; ++i) rhs[i] = offDiagonal(random);
  Eigen::VectorXd x;
  EXPECT_TRUE(backend.solve(rhs, x));
  return x;
}

TEST(CholmodOrdering, HeavyFillTakesTheOrderingWithFewerFlops) {
  const BlockPattern pattern = lattice(60);
  CholmodBackend amd(CholmodOrdering::kAmd), leastWork(CholmodOrdering::kLeastWork);
  amd.analyze(pattern.dims, pattern.pairs);
  leastWork.analyze(pattern.dims, pattern.pairs);
  EXPECT_STREQ(amd.orderingName(), "amd");
  EXPECT_STREQ(leastWork.orderingName(), "metis");
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

}  // namespace
}  // namespace lrsvo::test
