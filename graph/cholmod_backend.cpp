#include "lrsvo/graph/cholmod_backend.h"

#include <algorithm>
#include <vector>

#include "lrsvo/graph/error.h"
#include "lrsvo/graph/openmp_thread_limit.h"

namespace lrsvo {

namespace {

// The factor's fill, relative to the matrix's, from which METIS is tried too
// (CHOLMOD's own threshold for it, without the flops-per-entry condition).
constexpr double kHeavyFill = 5.0;

// The supernodal factorisation makes a few dense BLAS calls per supernode.
// Below this many flops per supernode on average (a planar pose graph's
// supernodes hold about three poses) the calls' overhead outweighs their
// speed, and the simplicial factorisation, column by column, is faster
// (docs/pose_graphs.md: `lrsvo bench graph` on the generated graphs).
constexpr double kMinFlopsPerSupernode = 1e5;

const char* nameOf(int ordering) {
  switch (ordering) {
    case CHOLMOD_NATURAL: return "natural";
    case CHOLMOD_GIVEN: return "given";
    case CHOLMOD_AMD: return "amd";
    case CHOLMOD_METIS: return "metis";
    case CHOLMOD_NESDIS: return "nesdis";
    case CHOLMOD_COLAMD: return "colamd";
    case CHOLMOD_POSTORDERED: return "postordered";
    default: return "unknown";
  }
}

// The pattern of the blocks' upper triangle, one row and column per block,
// from each column's pairs (indices into blockPairs, in row order).
cholmod_sparse* blockGraph(const std::vector<std::vector<int>>& columnPairs,
                           const std::vector<std::pair<int, int>>& blockPairs, cholmod_common* common) {
  const auto blockCount = columnPairs.size();
  cholmod_sparse* graph = cholmod_allocate_sparse(blockCount, blockCount, blockPairs.size(), /*sorted=*/1,
                                                  /*packed=*/1, /*stype=*/1, CHOLMOD_PATTERN, common);
  if (!graph) return nullptr;
  auto* colPtr = static_cast<int*>(graph->p);
  auto* rowIdx = static_cast<int*>(graph->i);
  int position = 0;
  for (std::size_t c = 0; c < blockCount; ++c) {
    colPtr[c] = position;
    for (int pair : columnPairs[c]) rowIdx[position++] = blockPairs[static_cast<std::size_t>(pair)].first;
  }
  colPtr[blockCount] = position;
  return graph;
}

// A permutation of the blocks as one of the scalars: each block's unknowns
// together, in their order. offsets: each block's first scalar, and the total.
std::vector<int> scalarPermutation(const std::vector<int>& blockOrder, const std::vector<int>& offsets) {
  std::vector<int> permutation;
  permutation.reserve(static_cast<std::size_t>(offsets.back()));
  for (int block : blockOrder)
    for (int k = offsets[static_cast<std::size_t>(block)]; k < offsets[static_cast<std::size_t>(block) + 1]; ++k)
      permutation.push_back(k);
  return permutation;
}

}  // namespace

CholmodBackend::CholmodBackend(CholmodOrdering ordering) : ordering_(ordering) {
  cholmod_start(&common_);
  common_.print = 0;
  common_.supernodal = CHOLMOD_SUPERNODAL;
  // A simplicial factor is LL' too, so a matrix that is not positive definite
  // is reported by either kind (LDL' would factorise it).
  common_.final_ll = 1;
}

CholmodBackend::~CholmodBackend() {
  release();
  cholmod_finish(&common_);
}

void CholmodBackend::release() {
  orderingName_ = "none";
  factorizationFlops_ = 0.0;
  if (factor_) cholmod_free_factor(&factor_, &common_);
  if (matrix_) cholmod_free_sparse(&matrix_, &common_);
}

void CholmodBackend::analyze(const std::vector<int>& blockDims, const std::vector<std::pair<int, int>>& blockPairs) {
  release();
  const int blockCount = static_cast<int>(blockDims.size());
  std::vector<int> offsets(blockCount + 1, 0);
  for (int i = 0; i < blockCount; ++i) offsets[i + 1] = offsets[i] + blockDims[i];
  const int n = offsets.back();

  // Block rows of every block column, in row order, and where block k sits.
  std::vector<std::vector<int>> columnPairs(blockCount);
  for (int k = 0; k < static_cast<int>(blockPairs.size()); ++k) columnPairs[blockPairs[k].second].push_back(k);
  std::vector<int> rowPosition(blockPairs.size()), columnLength(blockCount, 0);
  std::size_t nnz = 0;
  for (int c = 0; c < blockCount; ++c) {
    auto& pairs = columnPairs[c];
    std::sort(pairs.begin(), pairs.end(), [&](int a, int b) { return blockPairs[a].first < blockPairs[b].first; });
    for (int k : pairs) {
      rowPosition[k] = columnLength[c];
      columnLength[c] += blockDims[blockPairs[k].first];
    }
    nnz += static_cast<std::size_t>(columnLength[c]) * blockDims[c];
  }

  matrix_ = cholmod_allocate_sparse(n, n, nnz, /*sorted=*/1, /*packed=*/1, /*stype=*/1, CHOLMOD_REAL, &common_);
  if (!matrix_) throw Error("cholmod: cannot allocate a " + std::to_string(n) + "x" + std::to_string(n) + " matrix");
  auto* colPtr = static_cast<int*>(matrix_->p);
  auto* rowIdx = static_cast<int*>(matrix_->i);
  auto* values = static_cast<double*>(matrix_->x);
  int position = 0;
  for (int c = 0; c < blockCount; ++c) {
    for (int k = 0; k < blockDims[c]; ++k) {
      colPtr[offsets[c] + k] = position;
      for (int pair : columnPairs[c]) {
        const int row = blockPairs[pair].first;
        for (int r = 0; r < blockDims[row]; ++r) rowIdx[position++] = offsets[row] + r;
      }
    }
  }
  colPtr[n] = position;

  blocks_.resize(blockPairs.size());
  for (int k = 0; k < static_cast<int>(blockPairs.size()); ++k) {
    const int c = blockPairs[k].second;
    blocks_[k] = {values + colPtr[offsets[c]] + rowPosition[k], columnLength[c]};
  }
  setZero();
  factor_ = cholmod_analyze(matrix_, &common_);
  if (!factor_) throw Error("cholmod: symbolic analysis failed");
  factorizationFlops_ = common_.fl;
  orderingName_ = nameOf(factor_->ordering);
  if (ordering_ == CholmodOrdering::kLeastWork) {
    // The upper triangle's entries: diagonal blocks are stored whole.
    double upperEntries = static_cast<double>(nnz);
    for (int d : blockDims) upperEntries -= 0.5 * d * (d - 1);
    if (common_.lnz >= kHeavyFill * upperEntries) tryNestedDissection(offsets, columnPairs, blockPairs);
  }
  chooseFactorizationKind();
}

cholmod_factor* CholmodBackend::analyzeWith(const int* permutation, int kind) {
  const int methods = common_.nmethods, defaultOrdering = common_.method[0].ordering, defaultKind = common_.supernodal;
  common_.nmethods = 1;
  common_.method[0].ordering = CHOLMOD_GIVEN;
  common_.supernodal = kind;
  cholmod_factor* factor = cholmod_analyze_p(matrix_, const_cast<int*>(permutation), nullptr, 0, &common_);
  common_.nmethods = methods;
  common_.method[0].ordering = defaultOrdering;
  common_.supernodal = defaultKind;
  return factor;
}

void CholmodBackend::chooseFactorizationKind() {
  if (!factor_->is_super || factor_->nsuper == 0) return;
  if (factorizationFlops_ / static_cast<double>(factor_->nsuper) >= kMinFlopsPerSupernode) return;
  // The same ordering, analysed for the simplicial factorisation.
  cholmod_factor* simplicial = analyzeWith(static_cast<const int*>(factor_->Perm), CHOLMOD_SIMPLICIAL);
  if (!simplicial) return;  // the supernodal analysis stands
  cholmod_free_factor(&factor_, &common_);
  factor_ = simplicial;
}

void CholmodBackend::tryNestedDissection(const std::vector<int>& offsets,
                                         const std::vector<std::vector<int>>& columnPairs,
                                         const std::vector<std::pair<int, int>>& blockPairs) {
  cholmod_sparse* graph = blockGraph(columnPairs, blockPairs, &common_);
  if (!graph) return;  // CHOLMOD's own ordering stands
  std::vector<int> blockOrder(columnPairs.size()), parent(blockOrder.size()), member(blockOrder.size());
  for (const int method : {CHOLMOD_METIS, CHOLMOD_NESDIS}) {
    // Either fails when METIS is missing or out of memory: the others stand.
    const bool ordered = method == CHOLMOD_METIS
                             ? cholmod_metis(graph, nullptr, 0, /*postorder=*/1, blockOrder.data(), &common_) != 0
                             : cholmod_nested_dissection(graph, nullptr, 0, blockOrder.data(), parent.data(),
                                                         member.data(), &common_) >= 0;
    if (!ordered) continue;
    const std::vector<int> permutation = scalarPermutation(blockOrder, offsets);
    cholmod_factor* candidate = analyzeWith(permutation.data(), CHOLMOD_SUPERNODAL);
    if (!candidate) continue;
    if (common_.fl < factorizationFlops_) {
      cholmod_free_factor(&factor_, &common_);
      factor_ = candidate;
      factorizationFlops_ = common_.fl;
      orderingName_ = nameOf(method);
    } else {
      cholmod_free_factor(&candidate, &common_);
    }
  }
  cholmod_free_sparse(&graph, &common_);
}

void CholmodBackend::setZero() { std::fill_n(static_cast<double*>(matrix_->x), matrix_->nzmax, 0.0); }

bool CholmodBackend::solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& x, int threads) {
  const OpenMpThreadLimit limit(threads);
  cholmod_factorize(matrix_, factor_, &common_);
  if (common_.status == CHOLMOD_NOT_POSDEF || factor_->minor < factor_->n) return false;
  cholmod_dense b;
  b.nrow = b.d = rhs.size();
  b.ncol = 1;
  b.nzmax = rhs.size();
  b.x = const_cast<double*>(rhs.data());
  b.z = nullptr;
  b.xtype = CHOLMOD_REAL;
  b.dtype = CHOLMOD_DOUBLE;
  cholmod_dense* solution = cholmod_solve(CHOLMOD_A, factor_, &b, &common_);
  if (!solution) return false;
  x = Eigen::Map<const Eigen::VectorXd>(static_cast<double*>(solution->x), rhs.size());
  cholmod_free_dense(&solution, &common_);
  return x.allFinite();
}

}  // namespace lrsvo
