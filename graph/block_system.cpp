#include "lrsvo/graph/block_system.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>

#include "lrsvo/graph/block_kernels.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/parallel_for.h"

namespace lrsvo {

namespace {

// Active vertices (non-fixed, on at least one edge) in graph order, free ones
// first when the Schur ordering is asked for.
std::vector<Vertex*> orderVertices(const Graph& graph, bool schurOrdering, int* freeCount) {
  std::unordered_map<const Vertex*, bool> used;
  for (const auto& edge : graph.edges())
    for (Vertex* v : edge->vertices())
      if (!v->fixed()) used[v] = true;
  std::vector<Vertex*> free, marginalised;
  for (const auto& v : graph.vertices()) {
    if (!used.count(v.get())) continue;
    (schurOrdering && v->marginalized() ? marginalised : free).push_back(v.get());
  }
  *freeCount = static_cast<int>(free.size());
  free.insert(free.end(), marginalised.begin(), marginalised.end());
  return free;
}

// items sorted by key(item) in [0, keyCount), items of one key in their order.
template <typename Items, typename Key>
Items stableCountingSort(const Items& items, int keyCount, const Key& key) {
  std::vector<std::size_t> start(static_cast<std::size_t>(keyCount) + 1, 0);
  for (const auto& item : items) ++start[static_cast<std::size_t>(key(item)) + 1];
  for (std::size_t k = 0; k < static_cast<std::size_t>(keyCount); ++k) start[k + 1] += start[k];
  Items sorted(items.size());
  for (const auto& item : items) sorted[start[static_cast<std::size_t>(key(item))]++] = item;
  return sorted;
}

}  // namespace

BlockSystem::BlockSystem(const Graph& graph, bool schurOrdering) {
  if (graph.empty()) throw Error("optimise: the graph has no vertices");
  if (graph.edges().empty()) throw Error("optimise: the graph has no edges");
  vertices_ = orderVertices(graph, schurOrdering, &freeCount_);
  if (vertices_.empty()) throw Error("optimise: every vertex on an edge is fixed; nothing to optimise");

  std::unordered_map<const Vertex*, int>& index = blockIndex_;
  index.reserve(vertices_.size());
  for (int i = 0; i < blockCount(); ++i) {
    index[vertices_[i]] = i;
    dims_.push_back(vertices_[i]->dimension());
    offsets_.push_back(scalarCount_);
    scalarCount_ += dims_.back();
  }

  // Every pair (row <= col) of an edge's active vertices, in edge order.
  struct Entry {
    int row;
    int col;
    Contribution contribution;
  };
  // At most every pair of each edge's vertices: reserved once, as growing
  // the array would copy it and hold two copies at once.
  std::size_t pairBound = 0;
  for (const auto& edge : graph.edges())
    pairBound += static_cast<std::size_t>(edge->vertexCount()) * (edge->vertexCount() + 1) / 2;
  LargeArray<Entry> entries;
  entries.reserve(pairBound);
  std::vector<int> edgeBlocks;  // block index of each of an edge's vertices, -1 if inactive
  for (const auto& edgePtr : graph.edges()) {
    Edge* edge = edgePtr.get();
    edges_.push_back(edge);
    edgeBlocks.assign(static_cast<std::size_t>(edge->vertexCount()), -1);
    for (int a = 0; a < edge->vertexCount(); ++a) {
      const auto found = index.find(edge->vertex(a));
      if (found != index.end()) edgeBlocks[static_cast<std::size_t>(a)] = found->second;
    }
    for (int a = 0; a < edge->vertexCount(); ++a) {
      const int row = edgeBlocks[static_cast<std::size_t>(a)];
      if (row < 0) continue;
      for (int b = 0; b < edge->vertexCount(); ++b) {
        const int col = edgeBlocks[static_cast<std::size_t>(b)];
        if (col < 0 || row > col) continue;
        if (row == col && a != b)
          throw Error(std::string("edge ") + edge->typeTag() + " names vertex " +
                      std::to_string(edge->vertex(a)->id()) + " twice");
        entries.push_back({row, col, {edge, a, b}});
      }
    }
  }
  // Grouped by pair, column by column and row by row, each pair's edges in
  // edge order (the order H's blocks sum them in).
  entries = stableCountingSort(entries, blockCount(), [](const Entry& e) { return e.row; });
  entries = stableCountingSort(entries, blockCount(), [](const Entry& e) { return e.col; });

  // Block ids: the diagonal of vertex i is block i, the others follow in
  // that order. colBlockIds_ lists every block in that order.
  for (int i = 0; i < blockCount(); ++i) blocks_.push_back(Block{i, i, 0});
  LargeArray<int> entryBlock(entries.size());
  rowStart_.assign(blockCount() + 1, 0);
  colStart_.assign(blockCount() + 1, 0);
  for (std::size_t e = 0; e < entries.size(); ++e) {
    const Entry& entry = entries[e];
    const bool newPair = e == 0 || entry.row != entries[e - 1].row || entry.col != entries[e - 1].col;
    if (newPair && entry.row != entry.col) blocks_.push_back(Block{entry.row, entry.col, 0});
    entryBlock[e] = entry.row == entry.col ? entry.row : static_cast<int>(blocks_.size()) - 1;
    if (newPair) {
      colBlockIds_.push_back(entryBlock[e]);
      ++rowStart_[entry.row + 1];
      ++colStart_[entry.col + 1];
    }
  }
  for (int i = 0; i < blockCount(); ++i) {
    rowStart_[i + 1] += rowStart_[i];
    colStart_[i + 1] += colStart_[i];
  }

  contributionStart_.assign(blocks_.size() + 1, 0);
  for (int id : entryBlock) ++contributionStart_[static_cast<std::size_t>(id) + 1];
  for (std::size_t k = 0; k < blocks_.size(); ++k) contributionStart_[k + 1] += contributionStart_[k];
  contributions_.resize(entries.size());
  std::vector<std::size_t> next(contributionStart_.begin(), contributionStart_.end() - 1);
  for (std::size_t e = 0; e < entries.size(); ++e)
    contributions_[next[static_cast<std::size_t>(entryBlock[e])]++] = entries[e].contribution;
  // Released before H's values are allocated, so the set-up's peak memory is
  // the larger of the two, not their sum.
  LargeArray<Entry>().swap(entries);
  LargeArray<int>().swap(entryBlock);

  // Each row's blocks listed by column.
  rowBlockIds_.resize(colBlockIds_.size());
  std::vector<std::size_t> nextInRow(rowStart_.begin(), rowStart_.end() - 1);
  for (int id : colBlockIds_)
    rowBlockIds_[nextInRow[static_cast<std::size_t>(blocks_[static_cast<std::size_t>(id)].row)]++] = id;
  // Values laid out by column, then row: a marginalised vertex's couplings and
  // its diagonal block are contiguous, for the Schur solvers' point-by-point
  // passes and fill()'s column-by-column sums.
  std::size_t size = 0;
  for (int id : colBlockIds_) {
    Block& block = blocks_[static_cast<std::size_t>(id)];
    block.offset = size;
    size += static_cast<std::size_t>(dims_[block.row]) * dims_[block.col];
  }
  values_.assign(size, 0.0);
  gradient_ = Eigen::VectorXd::Zero(scalarCount_);
  diagonal_ = Eigen::VectorXd::Zero(scalarCount_);
}

int BlockSystem::blockOf(const Vertex* vertex) const {
  auto it = blockIndex_.find(vertex);
  return it == blockIndex_.end() ? -1 : it->second;
}

double BlockSystem::fill(int threads) {
  const int edgeCount = static_cast<int>(edges_.size());
  std::vector<double> costs(edgeCount);
  parallelFor(0, edgeCount, threads, [&](int e) { costs[e] = edges_[e]->linearize(); });

  // Column by column: the blocks of one column share their edges (a point's
  // W blocks and its V block), so each edge is read from memory once per
  // column and found in cache for the column's other blocks.
  parallelFor(0, blockCount(), threads, [&](int column) {
    for (int k : colBlocks(column)) fillBlock(k);
  });

  heldScalars_.clear();
  double total = 0.0;
  for (double c : costs) total += c;
  return total;
}

void BlockSystem::fillBlock(int k) {
  const Block& block = blocks_[k];
  double* target = values(block);
  const int rows = dims_[block.row];
  std::fill(target, target + rows * dims_[block.col], 0.0);
  const std::span<const Contribution> edges = slice(contributions_, contributionStart_, k);
  if (k >= blockCount()) {
    for (const Contribution& c : edges) c.edge->addHessianBlock(c.a, c.b, target, rows);
    return;
  }
  // Diagonal block k: the edges on vertex k, which also make its gradient,
  // taken while each edge is in cache.
  double* g = gradient_.data() + offsets_[k];
  std::fill(g, g + rows, 0.0);
  for (const Contribution& c : edges) {
    c.edge->addHessianBlock(c.a, c.a, target, rows);
    c.edge->addGradient(c.a, g);
  }
  for (int d = 0; d < rows; ++d) diagonal_[offsets_[k] + d] = target[d * rows + d];
}

double BlockSystem::cost(int threads) const {
  const int edgeCount = static_cast<int>(edges_.size());
  std::vector<double> costs(edgeCount);
  parallelFor(0, edgeCount, threads, [&](int e) { costs[e] = edges_[e]->cost(); });
  double total = 0.0;
  for (double c : costs) total += c;
  return total;
}

void BlockSystem::setDiagonalShift(const Eigen::VectorXd& shift) {
  for (int i = 0; i < blockCount(); ++i) {
    double* diag = values(blocks_[diagonalBlock(i)]);
    for (int d = 0; d < dims_[i]; ++d) diag[d * dims_[i] + d] = diagonal_[offsets_[i] + d] + shift[offsets_[i] + d];
  }
}

void BlockSystem::holdCoordinate(int block, int coordinate) {
  const int d = dims_[block];
  for (int k : rowBlocks(block)) {
    const int cols = dims_[blocks_[k].col];
    for (int c = 0; c < cols; ++c) values(blocks_[k])[c * d + coordinate] = 0.0;
  }
  for (int k : colBlocks(block)) {
    const int rows = dims_[blocks_[k].row];
    std::fill_n(values(blocks_[k]) + coordinate * rows, rows, 0.0);
  }
  values(blocks_[diagonalBlock(block)])[coordinate * d + coordinate] = 1.0;
  diagonal_[offsets_[block] + coordinate] = 1.0;
  gradient_[offsets_[block] + coordinate] = 0.0;
  heldScalars_.push_back(offsets_[block] + coordinate);
}

Eigen::VectorXd BlockSystem::multiply(const Eigen::VectorXd& x) const {
  Eigen::VectorXd y = Eigen::VectorXd::Zero(scalarCount_);
  for (const Block& block : blocks_) {
    const int rows = dims_[block.row], cols = dims_[block.col];
    kernels::accumulateBlock<false>(values(block), x.data() + offsets_[block.col], y.data() + offsets_[block.row], rows,
                                    cols, 1.0);
    if (block.row != block.col)
      kernels::accumulateBlock<true>(values(block), x.data() + offsets_[block.row], y.data() + offsets_[block.col],
                                     rows, cols, 1.0);
  }
  return y;
}

Eigen::VectorXd BlockSystem::secondDirectionalGradient(const Eigen::VectorXd& dx, double h) {
  saveEstimates();
  applyStep(h * dx);
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(scalarCount_);
  std::vector<const double*> steps;
  std::vector<double*> gradients;
  for (const Edge* edge : edges_) {
    steps.assign(edge->vertexCount(), nullptr);
    gradients.assign(edge->vertexCount(), nullptr);
    for (int k = 0; k < edge->vertexCount(); ++k) {
      const int block = blockOf(edge->vertex(k));
      if (block < 0) continue;
      steps[k] = dx.data() + offsets_[block];
      gradients[k] = sum.data() + offsets_[block];
    }
    edge->addSecondDirectionalGradient(h, steps.data(), gradients.data());
  }
  restoreEstimates();
  for (int scalar : heldScalars_) sum[scalar] = 0.0;
  return sum;
}

void BlockSystem::applyStep(const Eigen::VectorXd& dx) {
  for (int i = 0; i < blockCount(); ++i) vertices_[i]->oplus(dx.data() + offsets_[i]);
}

void BlockSystem::saveEstimates() {
  if (estimateOffsets_.empty()) {
    std::size_t size = 0;
    for (Vertex* v : vertices_) {
      estimateOffsets_.push_back(size);
      size += v->estimateSize();
    }
    savedEstimates_.resize(size);
  }
  for (int i = 0; i < blockCount(); ++i) vertices_[i]->getEstimate(savedEstimates_.data() + estimateOffsets_[i]);
}

void BlockSystem::restoreEstimates() {
  for (int i = 0; i < blockCount(); ++i) vertices_[i]->setEstimate(savedEstimates_.data() + estimateOffsets_[i]);
}

}  // namespace lrsvo
