#include "lrsvo/graph/block_system.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>

#include "lrsvo/graph/balanced_ranges.h"
#include "lrsvo/graph/block_kernels.h"
#include "lrsvo/graph/edge_costs.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/parallel_for.h"
#include "lrsvo/graph/vertex_positions.h"

namespace lrsvo {

namespace {

// At most this many ranges of marginalised columns, each with its partial sums
// of the free-free blocks: enough for the threads of a workstation, and fixed,
// so that a sum's order depends on the problem alone.
constexpr int kMaxCarriedRanges = 8;
// A range of columns is worth its partial sums when its carried entries
// outnumber them this many times.
constexpr double kPartialSumsPayback = 8.0;

// Each edge's vertex count, then the graph position of each of its vertices
// (-1 for one not in the graph), edge by edge in graph order: every lookup
// of the set-up, made once.
LargeArray<int> edgeVertexPositions(const Graph& graph, const VertexPositions& positions) {
  std::size_t size = 0;
  for (const auto& edge : graph.edges()) size += 1 + static_cast<std::size_t>(edge->vertexCount());
  LargeArray<int> list(size);
  std::size_t next = 0;
  for (const auto& edge : graph.edges()) {
    const int n = edge->vertexCount();
    if (n > std::numeric_limits<std::int16_t>::max())
      throw Error(std::string("edge ") + edge->typeTag() + " joins " + std::to_string(n) + " vertices; at most " +
                  std::to_string(std::numeric_limits<std::int16_t>::max()) + " are supported");
    list[next++] = n;
    for (int a = 0; a < n; ++a) list[next++] = positions.find(edge->vertex(a));
  }
  return list;
}

// Calls visit(entry) on each vertex's entry of a list laid out as
// edgeVertexPositions lays it out (each edge's vertex count, then an entry per
// vertex), in order.
template <typename List, typename Visit>
void forEachVertexEntry(List& list, const Visit& visit) {
  for (std::size_t next = 0; next < list.size();) {
    const int n = list[next++];
    for (int a = 0; a < n; ++a) visit(list[next++]);
  }
}

// Active vertices (non-fixed, on at least one edge) in graph order, free ones
// first when the Schur ordering is asked for.
std::vector<Vertex*> orderVertices(const Graph& graph, const LargeArray<int>& vertexPositions, bool schurOrdering,
                                   int* freeCount) {
  std::vector<char> used(graph.vertices().size(), 0);
  forEachVertexEntry(vertexPositions, [&](int position) {
    if (position >= 0 && !graph.vertices()[static_cast<std::size_t>(position)]->fixed())
      used[static_cast<std::size_t>(position)] = 1;
  });
  std::vector<Vertex*> free, marginalised;
  for (std::size_t i = 0; i < used.size(); ++i) {
    if (!used[i]) continue;
    Vertex* v = graph.vertices()[i].get();
    (schurOrdering && v->marginalized() ? marginalised : free).push_back(v);
  }
  *freeCount = static_cast<int>(free.size());
  free.insert(free.end(), marginalised.begin(), marginalised.end());
  return free;
}

// Stable sort of a short range by key: insertion sort where std::stable_sort
// would allocate a buffer for a handful of items.
template <typename Iterator, typename Key>
void stableSortBy(Iterator first, Iterator last, const Key& key) {
  if (last - first > 32) {
    std::stable_sort(first, last, [&](const auto& x, const auto& y) { return key(x) < key(y); });
    return;
  }
  for (Iterator i = first + 1; i < last; ++i) {
    auto item = *i;
    Iterator j = i;
    for (; j > first && key(*(j - 1)) > key(item); --j) *j = *(j - 1);
    *j = item;
  }
}

// One pair (row <= col) of an edge's active vertices, in its column's list.
struct PairSlot {
  int row;
  int carrier;  // for a free-free pair of an edge on a marginalised vertex: that vertex's block, else -1
  Edge* edge;
  int a;  // the edge's local index of the row vertex
  int b;  // the edge's local index of the column vertex
};

// Stable sort of pairs whose rows lie in [0, maxRow], by row: counts, then
// places, through `scratch` (kept for the next call).
template <typename Iterator>
void countingSortByRow(Iterator first, Iterator last, int maxRow, std::vector<PairSlot>& scratch,
                       std::vector<std::size_t>& counts) {
  counts.assign(static_cast<std::size_t>(maxRow) + 2, 0);
  for (Iterator slot = first; slot != last; ++slot) ++counts[static_cast<std::size_t>(slot->row) + 1];
  for (std::size_t r = 0; r + 1 < counts.size(); ++r) counts[r + 1] += counts[r];
  scratch.assign(first, last);
  for (const PairSlot& slot : scratch) *(first + static_cast<std::ptrdiff_t>(counts[slot.row]++)) = slot;
}

// Each edge's vertex count, then the block of each of its vertices (-1 for a
// fixed one), edge by edge in graph order: edgeVertexPositions with each
// position replaced by its block.
LargeArray<int> edgeVertexBlocks(LargeArray<int> list, const std::vector<int>& blockOfPosition) {
  forEachVertexEntry(list, [&](int& entry) {
    if (entry >= 0) entry = blockOfPosition[static_cast<std::size_t>(entry)];
  });
  return list;
}

// Calls visit(row, col, carrier, edge, a, b) for every pair of an edge's
// active vertices with row <= col, edge by edge in graph order, from the
// edges' vertex blocks (edgeVertexBlocks). The carrier of a pair of free
// vertices (blocks below freeCount) is the edge's first marginalised vertex,
// -1 when it has none or the pair is not free-free.
template <typename Visit>
void forEachPair(const Graph& graph, const LargeArray<int>& vertexBlocks, int freeCount, const Visit& visit) {
  const int* next = vertexBlocks.data();
  for (const auto& edgePtr : graph.edges()) {
    Edge* edge = edgePtr.get();
    const int n = *next++;
    const int* edgeBlocks = next;
    next += n;
    int carrier = -1;
    for (int a = 0; a < n; ++a)
      if (edgeBlocks[a] >= freeCount && (carrier < 0 || edgeBlocks[a] < carrier)) carrier = edgeBlocks[a];
    for (int a = 0; a < n; ++a) {
      const int row = edgeBlocks[a];
      if (row < 0) continue;
      for (int b = 0; b < n; ++b) {
        const int col = edgeBlocks[b];
        if (col >= 0 && row <= col) visit(row, col, col < freeCount ? carrier : -1, edge, a, b);
      }
    }
  }
}

// Every pair, bucketed by column in two passes over the edges (count, then
// place) and sorted by row within its column, each pair's edges in edge order
// (the order H's blocks sum them in): no list of all pairs is sorted or
// copied. A column's diagonal pairs (row == col, the largest row) are placed
// at its end as they come, so only the others are sorted; a graph built frame
// by frame gives them in row order already. columnStart gets the buckets'
// bounds (CSR).
LargeArray<PairSlot> pairsByColumn(const Graph& graph, const LargeArray<int>& vertexBlocks, int blockCount,
                                   int freeCount, std::vector<std::size_t>* columnStart) {
  std::vector<std::size_t>& start = *columnStart;
  start.assign(static_cast<std::size_t>(blockCount) + 1, 0);
  std::vector<std::size_t> diagonals(static_cast<std::size_t>(blockCount), 0);
  forEachPair(graph, vertexBlocks, freeCount, [&](int row, int col, int, const Edge* edge, int a, int b) {
    if (row == col && a != b)
      throw Error(std::string("edge ") + edge->typeTag() + " names vertex " + std::to_string(edge->vertex(a)->id()) +
                  " twice");
    ++start[static_cast<std::size_t>(col) + 1];
    if (row == col) ++diagonals[static_cast<std::size_t>(col)];
  });
  for (std::size_t c = 0; c + 1 < start.size(); ++c) start[c + 1] += start[c];
  LargeArray<PairSlot> slots(start.back());
  std::vector<std::size_t> next(start.begin(), start.end() - 1), nextDiagonal(diagonals.size());
  for (std::size_t c = 0; c < diagonals.size(); ++c) nextDiagonal[c] = start[c + 1] - diagonals[c];
  forEachPair(graph, vertexBlocks, freeCount, [&](int row, int col, int carrier, Edge* edge, int a, int b) {
    std::size_t& place = (row == col ? nextDiagonal : next)[static_cast<std::size_t>(col)];
    slots[place++] = PairSlot{row, carrier, edge, a, b};
  });
  std::vector<PairSlot> scratch;
  std::vector<std::size_t> rowCounts;
  for (std::size_t c = 0; c + 1 < start.size(); ++c) {
    const auto first = slots.begin() + static_cast<std::ptrdiff_t>(start[c]);
    const auto last = slots.begin() + static_cast<std::ptrdiff_t>(start[c + 1] - diagonals[c]);
    if (std::is_sorted(first, last, [](const PairSlot& x, const PairSlot& y) { return x.row < y.row; })) continue;
    // The rows lie in [0, c). Where the column holds more pairs than that (a
    // vertex early in the order shared by many edges, such as the stereo
    // extrinsic), a counting sort orders it in one pass.
    if (static_cast<std::ptrdiff_t>(c) < last - first)
      countingSortByRow(first, last, static_cast<int>(c), scratch, rowCounts);
    else
      stableSortBy(first, last, [](const PairSlot& slot) { return slot.row; });
  }
  return slots;
}

}  // namespace

BlockSystem::BlockSystem(const Graph& graph, bool schurOrdering) : schurOrdering_(schurOrdering) {
  if (graph.empty()) throw Error("optimise: the graph has no vertices");
  if (graph.edges().empty()) throw Error("optimise: the graph has no edges");
  std::vector<const Vertex*> graphVertices;
  graphVertices.reserve(graph.vertices().size());
  for (const auto& v : graph.vertices()) graphVertices.push_back(v.get());
  const VertexPositions positions(graphVertices);
  LargeArray<int> vertexPositions = edgeVertexPositions(graph, positions);
  vertices_ = orderVertices(graph, vertexPositions, schurOrdering, &freeCount_);
  if (vertices_.empty()) throw Error("optimise: every vertex on an edge is fixed; nothing to optimise");

  // The block of each graph position, -1 for fixed vertices and those on no edge.
  std::vector<int> blockOfPosition(graphVertices.size(), -1);
  blockIndex_.reserve(vertices_.size());
  for (int i = 0; i < blockCount(); ++i) {
    blockIndex_[vertices_[i]] = i;
    blockOfPosition[static_cast<std::size_t>(positions.find(vertices_[i]))] = i;
    dims_.push_back(vertices_[i]->dimension());
    offsets_.push_back(scalarCount_);
    scalarCount_ += dims_.back();
  }

  edges_.reserve(graph.edges().size());
  for (const auto& edge : graph.edges()) edges_.push_back(edge.get());
  edgeVertexBlocks_ = edgeVertexBlocks(std::move(vertexPositions), blockOfPosition);
  std::vector<std::size_t> columnStart;
  LargeArray<PairSlot> slots = pairsByColumn(graph, edgeVertexBlocks_, blockCount(), freeCount_, &columnStart);

  // Block ids: the diagonal of vertex i is block i, the others follow column
  // by column, row by row (a column's diagonal, row == col, ends it);
  // colBlockIds_ lists every block in that order. The contributions go by
  // block id: the diagonals' first, in column order, then the others in the
  // order of the walk. A carried pair goes to its carrier's list instead, in
  // the order of the walk.
  for (int i = 0; i < blockCount(); ++i) blocks_.push_back(Block{i, i, 0});
  rowStart_.assign(blockCount() + 1, 0);
  colStart_.assign(blockCount() + 1, 0);
  // Each block's (each carrier's) contribution count at [id + 1], summed into
  // the starts below.
  contributionStart_.assign(static_cast<std::size_t>(blockCount()) + 1, 0);
  carriedStart_.assign(static_cast<std::size_t>(blockCount() - freeCount_) + 1, 0);
  // The block of the pair at a slot, given whether the slot starts a pair.
  int nextBlockId = blockCount();
  const auto blockAt = [&](const PairSlot& slot, int c, bool newPair) {
    return slot.row == c ? c : (newPair ? nextBlockId++ : nextBlockId - 1);
  };
  for (int c = 0; c < blockCount(); ++c) {
    const auto first = slots.begin() + static_cast<std::ptrdiff_t>(columnStart[static_cast<std::size_t>(c)]);
    const auto last = slots.begin() + static_cast<std::ptrdiff_t>(columnStart[static_cast<std::size_t>(c) + 1]);
    for (auto slot = first; slot != last; ++slot) {
      const bool newPair = slot == first || slot->row != (slot - 1)->row;
      const int id = blockAt(*slot, c, newPair);
      if (newPair) {
        if (id >= blockCount()) {
          blocks_.push_back(Block{slot->row, c, 0});
          contributionStart_.push_back(0);
        }
        colBlockIds_.push_back(id);
        ++rowStart_[slot->row + 1];
        ++colStart_[c + 1];
      }
      if (slot->carrier >= 0)
        ++carriedStart_[static_cast<std::size_t>(slot->carrier - freeCount_) + 1];
      else
        ++contributionStart_[static_cast<std::size_t>(id) + 1];
    }
  }
  for (int i = 0; i < blockCount(); ++i) {
    rowStart_[i + 1] += rowStart_[i];
    colStart_[i + 1] += colStart_[i];
  }
  for (std::size_t k = 0; k < blocks_.size(); ++k) contributionStart_[k + 1] += contributionStart_[k];
  for (std::size_t m = 0; m + 1 < carriedStart_.size(); ++m) carriedStart_[m + 1] += carriedStart_[m];
  contributions_.resize(contributionStart_.back());
  carried_.resize(carriedStart_.back());
  // The diagonals' contributions fill [0, start of the first other block).
  std::size_t nextDiagonal = 0, nextOther = contributionStart_[static_cast<std::size_t>(blockCount())];
  std::vector<std::size_t> nextCarried(carriedStart_.begin(), carriedStart_.end() - 1);
  nextBlockId = blockCount();
  for (int c = 0; c < blockCount(); ++c) {
    const std::size_t first = columnStart[static_cast<std::size_t>(c)];
    for (std::size_t e = first; e < columnStart[static_cast<std::size_t>(c) + 1]; ++e) {
      const PairSlot& slot = slots[e];
      const int id = blockAt(slot, c, e == first || slot.row != slots[e - 1].row);
      if (slot.carrier >= 0)
        carried_[nextCarried[static_cast<std::size_t>(slot.carrier - freeCount_)]++] = {
            slot.edge, id, static_cast<std::int16_t>(slot.a), static_cast<std::int16_t>(slot.b)};
      else
        contributions_[slot.row == c ? nextDiagonal++ : nextOther++] = {slot.edge, slot.a, slot.b};
    }
  }
  // Released before H's values are allocated, so the set-up's peak memory is
  // the larger of the two, not their sum.
  LargeArray<PairSlot>().swap(slots);

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
  freeValueCount_ = freeCount_ < blockCount()
                        ? blocks_[static_cast<std::size_t>(colBlockIds_[colStart_[freeCount_]])].offset
                        : values_.size();
  splitMarginalisedColumns();
}

void BlockSystem::splitMarginalisedColumns() {
  // A column's work: the entries its contributions sum.
  const int marginalised = blockCount() - freeCount_;
  std::vector<double> work(static_cast<std::size_t>(marginalised), 0.0);
  double carriedWork = 0.0;
  for (int m = 0; m < marginalised; ++m) {
    const int column = freeCount_ + m;
    for (int k : colBlocks(column)) {
      const Block& block = blocks_[static_cast<std::size_t>(k)];
      work[m] +=
          static_cast<double>(contributionStart_[k + 1] - contributionStart_[k]) * dims_[block.row] * dims_[block.col];
    }
    for (std::size_t c = carriedStart_[m]; c < carriedStart_[m + 1]; ++c) {
      const Block& block = blocks_[static_cast<std::size_t>(carried_[c].block)];
      const double entries = static_cast<double>(dims_[block.row]) * dims_[block.col];
      work[m] += entries;
      carriedWork += entries;
    }
  }
  // Each range zeroes its partial sums and each free block adds them all, so
  // a range pays where its carried entries outnumber the sums several times.
  partialSize_ = carried_.empty() ? 0 : freeValueCount_ + static_cast<std::size_t>(freeScalarCount());
  int ranges = marginalised > 0 ? 1 : 0;
  if (partialSize_ > 0)
    ranges = static_cast<int>(std::clamp(carriedWork / (kPartialSumsPayback * static_cast<double>(partialSize_)), 1.0,
                                         static_cast<double>(std::min(kMaxCarriedRanges, marginalised))));
  partialSums_.assign(static_cast<std::size_t>(ranges) * partialSize_, 0.0);

  marginalisedRanges_.assign(1, freeCount_);
  if (ranges == 0) return;
  marginalisedRanges_ = balancedRanges(work, ranges);
  for (int& bound : marginalisedRanges_) bound += freeCount_;
}

bool BlockSystem::describes(const Graph& graph, bool schurOrdering) const {
  if (schurOrdering != schurOrdering_ || graph.edges().size() != edges_.size()) return false;
  const int* next = edgeVertexBlocks_.data();
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const Edge* edge = graph.edges()[e].get();
    const int n = edge->vertexCount();
    if (edge != edges_[e] || *next++ != n) return false;
    for (int a = 0; a < n; ++a) {
      const int block = *next++;
      const Vertex* vertex = edge->vertex(a);
      // A vertex on an edge is inactive exactly when it is fixed.
      if (block < 0) {
        if (!vertex->fixed()) return false;
        continue;
      }
      if (vertex != vertices_[static_cast<std::size_t>(block)] || vertex->fixed() ||
          vertex->dimension() != dims_[static_cast<std::size_t>(block)] ||
          (schurOrdering_ && vertex->marginalized() != (block >= freeCount_)))
        return false;
    }
  }
  return true;
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
  // column and found in cache for the column's other blocks. The marginalised
  // columns first, range by range: their edges' free-free shares are summed
  // there, while the edges are in cache, so the free columns (a camera's
  // block, whose edges lie all over memory) only add up the ranges' sums.
  parallelFor(0, static_cast<int>(marginalisedRanges_.size()) - 1, threads, 1,
              [&](int range) { fillMarginalisedRange(range); });
  parallelFor(0, freeCount_, threads, [&](int column) {
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
  const std::size_t size = static_cast<std::size_t>(rows) * dims_[block.col];
  std::fill(target, target + size, 0.0);
  // A diagonal block's edges also make its gradient, taken while each edge is in cache.
  const bool diagonal = k < blockCount();
  double* g = diagonal ? gradient_.data() + offsets_[k] : nullptr;
  if (diagonal) std::fill(g, g + rows, 0.0);
  for (const Contribution& c : slice(contributions_, contributionStart_, k)) {
    c.edge->addHessianBlock(c.a, c.b, target, rows);
    if (diagonal) c.edge->addGradient(c.a, g);
  }
  if (block.col < freeCount_ && partialSize_ > 0) {
    const int ranges = static_cast<int>(marginalisedRanges_.size()) - 1;
    for (int r = 0; r < ranges; ++r) {
      const double* sums = partialSums(r);
      for (std::size_t i = 0; i < size; ++i) target[i] += sums[block.offset + i];
      if (diagonal)
        for (int d = 0; d < rows; ++d) g[d] += sums[freeValueCount_ + offsets_[k] + d];
    }
  }
  if (diagonal)
    for (int d = 0; d < rows; ++d) diagonal_[offsets_[k] + d] = target[d * rows + d];
}

void BlockSystem::fillMarginalisedRange(int r) {
  double* sums = partialSize_ > 0 ? partialSums(r) : nullptr;
  if (sums) std::fill(sums, sums + partialSize_, 0.0);
  for (int column = marginalisedRanges_[r]; column < marginalisedRanges_[r + 1]; ++column) {
    for (int k : colBlocks(column)) fillBlock(k);
    const std::size_t m = static_cast<std::size_t>(column - freeCount_);
    for (std::size_t c = carriedStart_[m]; c < carriedStart_[m + 1]; ++c) {
      const CarriedContribution& carried = carried_[c];
      const Block& block = blocks_[static_cast<std::size_t>(carried.block)];
      carried.edge->addHessianBlock(carried.a, carried.b, sums + block.offset, dims_[block.row]);
      if (carried.block < blockCount())
        carried.edge->addGradient(carried.a, sums + freeValueCount_ + offsets_[block.row]);
    }
  }
}

double BlockSystem::cost(int threads) const { return sumOfEdgeCosts(edges_, threads); }

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
