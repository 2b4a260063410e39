#pragma once

#include <cstddef>
#include <vector>

#include "lrsvo/graph/parallel_for.h"

namespace lrsvo {

// The sum of the edges' costs, evaluated on up to `threads` threads and added
// up in the edges' order: the same value, bit for bit, for any thread count.
// `edges` is a list of edge pointers (raw or owning).
template <typename EdgeList>
double sumOfEdgeCosts(const EdgeList& edges, int threads) {
  std::vector<double> costs(edges.size());
  parallelFor(0, static_cast<int>(edges.size()), threads,
              [&](int e) { costs[static_cast<std::size_t>(e)] = edges[static_cast<std::size_t>(e)]->cost(); });
  double total = 0.0;
  for (double c : costs) total += c;
  return total;
}

}  // namespace lrsvo
