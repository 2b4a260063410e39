#include "lrsvo/graph/vertex_positions.h"

#include <cstdint>

namespace lrsvo {

VertexPositions::VertexPositions(const std::vector<const Vertex*>& vertices) {
  // At most half full, so that a probe meets an empty slot within a few steps.
  int bits = 1;
  while ((std::size_t{1} << bits) < 2 * vertices.size()) ++bits;
  shift_ = 64 - bits;
  mask_ = (std::size_t{1} << bits) - 1;
  table_.assign(mask_ + 1, Entry{});
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    std::size_t slot = home(vertices[i]);
    while (table_[slot].vertex != nullptr && table_[slot].vertex != vertices[i]) slot = (slot + 1) & mask_;
    if (table_[slot].vertex == nullptr) table_[slot] = Entry{vertices[i], static_cast<int>(i)};
  }
}

std::size_t VertexPositions::home(const Vertex* vertex) const {
  // Fibonacci hashing: the high bits of the address times 2^64 / golden ratio.
  const auto address = static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(vertex));
  return static_cast<std::size_t>((address * 0x9E3779B97F4A7C15ull) >> shift_);
}

}  // namespace lrsvo
