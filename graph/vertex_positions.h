#pragma once

#include <cstddef>
#include <vector>

#include "lrsvo/graph/vertex.h"

namespace lrsvo {

// The position of each vertex of a list, found by its address: an open
// addressing table, probed linearly from a multiplicative hash. The block
// system looks up every vertex of every edge while it builds its structure,
// millions of times on large problems, where std::unordered_map would
// chase one heap node per lookup.
class VertexPositions {
 public:
  explicit VertexPositions(const std::vector<const Vertex*>& vertices);
  // Position of the vertex in the list, or -1 when it is not in it.
  int find(const Vertex* vertex) const {
    for (std::size_t slot = home(vertex);; slot = (slot + 1) & mask_) {
      const Entry& entry = table_[slot];
      if (entry.vertex == vertex) return entry.position;
      if (entry.vertex == nullptr) return -1;
    }
  }

 private:
  struct Entry {
    const Vertex* vertex = nullptr;
    int position = -1;
  };
  std::size_t home(const Vertex* vertex) const;

  std::vector<Entry> table_;
  std::size_t mask_ = 0;
  int shift_ = 0;
};

}  // namespace lrsvo
