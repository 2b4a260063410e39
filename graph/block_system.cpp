#include "graph/block_system.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <unordered_map>

#include "graph/error.h"
#include "graph/parallel_for.h"

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

}  // namespace

BlockSystem::BlockSystem(const Graph& graph, bool schurOrdering) {
  if (graph.empty()) throw Error("optimise: the graph has no vertices");
  if (graph.edges().empty()) throw Error("optimise: the graph has no edges");
  vertices_ = orderVertices(graph, schurOrdering, &freeCount_);
  if (vertices_.empty()) throw Error("optimise: every vertex on an edge is fixed; nothing to optimise");

  std::unordered_map<const Vertex*, int>& index = blockIndex_;
  for (int i = 0; i < blockCount(); ++i) {
    index[vertices_[i]] = i;
    dims_.push_back(vertices_[i]->dimension());
    offsets_.push_back(scalarCount_);
    scalarCount_ += dims_.back();
  }

  std::map<std::pair<int, int>, int> blockIds;
  gradientContributions_.resize(blockCount());
  auto blockId = [&](int row, int col) {
    auto [it, inserted] = blockIds.emplace(std::make_pair(row, col), static_cast<int>(blocks_.size()));
    if (inserted) {
      blocks_.push_back(Block{row, col, 0});
      blockContributions_.emplace_back();
    }
    return it->second;
  };
  for (int i = 0; i < blockCount(); ++i) blockId(i, i);
  for (const auto& edgePtr : graph.edges()) {
    Edge* edge = edgePtr.get();
    edges_.push_back(edge);
    for (int a = 0; a < edge->vertexCount(); ++a) {
      auto ia = index.find(edge->vertex(a));
      if (ia == index.end()) continue;
      gradientContributions_[ia->second].push_back({edge, a, a});
      for (int b = 0; b < edge->vertexCount(); ++b) {
        auto ib = index.find(edge->vertex(b));
        if (ib == index.end() || ia->second > ib->second) continue;
        if (ia->second == ib->second && a != b)
          throw Error(std::string("edge ") + edge->typeTag() + " names vertex " +
                      std::to_string(edge->vertex(a)->id()) + " twice");
        blockContributions_[blockId(ia->second, ib->second)].push_back({edge, a, b});
      }
    }
  }

  std::size_t size = 0;
  rowBlocks_.resize(blockCount());
  colBlocks_.resize(blockCount());
  for (auto& [key, id] : blockIds) {  // map order: by row, then column
    Block& block = blocks_[id];
    block.offset = size;
    size += static_cast<std::size_t>(dims_[block.row]) * dims_[block.col];
    rowBlocks_[block.row].push_back(id);
    colBlocks_[block.col].push_back(id);
  }
  for (auto& column : colBlocks_)
    std::sort(column.begin(), column.end(), [&](int x, int y) { return blocks_[x].row < blocks_[y].row; });
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

  parallelFor(0, static_cast<int>(blocks_.size()), threads, [&](int k) {
    const Block& block = blocks_[k];
    double* target = values(block);
    const int rows = dims_[block.row];
    std::fill(target, target + rows * dims_[block.col], 0.0);
    for (const Contribution& c : blockContributions_[k]) c.edge->addHessianBlock(c.a, c.b, target, rows);
  });
  parallelFor(0, blockCount(), threads, [&](int i) {
    double* g = gradient_.data() + offsets_[i];
    std::fill(g, g + dims_[i], 0.0);
    for (const Contribution& c : gradientContributions_[i]) c.edge->addGradient(c.a, g);
    const double* diag = values(blocks_[diagonalBlock(i)]);
    for (int d = 0; d < dims_[i]; ++d) diagonal_[offsets_[i] + d] = diag[d * dims_[i] + d];
  });

  double total = 0.0;
  for (double c : costs) total += c;
  return total;
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
    for (int d = 0; d < dims_[i]; ++d)
      diag[d * dims_[i] + d] = diagonal_[offsets_[i] + d] + shift[offsets_[i] + d];
  }
}

void BlockSystem::holdCoordinate(int block, int coordinate) {
  const int d = dims_[block];
  for (int k : rowBlocks_[block]) {
    const int cols = dims_[blocks_[k].col];
    for (int c = 0; c < cols; ++c) values(blocks_[k])[c * d + coordinate] = 0.0;
  }
  for (int k : colBlocks_[block]) {
    const int rows = dims_[blocks_[k].row];
    std::fill_n(values(blocks_[k]) + coordinate * rows, rows, 0.0);
  }
  values(blocks_[diagonalBlock(block)])[coordinate * d + coordinate] = 1.0;
  diagonal_[offsets_[block] + coordinate] = 1.0;
  gradient_[offsets_[block] + coordinate] = 0.0;
}

Eigen::VectorXd BlockSystem::multiply(const Eigen::VectorXd& x) const {
  Eigen::VectorXd y = Eigen::VectorXd::Zero(scalarCount_);
  for (const Block& block : blocks_) {
    Eigen::Map<const Eigen::MatrixXd> m(values(block), dims_[block.row], dims_[block.col]);
    y.segment(offsets_[block.row], dims_[block.row]) += m * x.segment(offsets_[block.col], dims_[block.col]);
    if (block.row != block.col)
      y.segment(offsets_[block.col], dims_[block.col]) +=
          m.transpose() * x.segment(offsets_[block.row], dims_[block.row]);
  }
  return y;
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
