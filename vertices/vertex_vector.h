#pragma once

#include "lrsvo/graph/vertex.h"

namespace lrsvo {

// A plain parameter vector of N numbers, updated by addition: the unknowns of
// a curve fit or of any model without a manifold of its own (a residual
// written in Python, say). Registered for N = 1 ... 9 as VECTOR1 ... VECTOR9.
template <int N>
class VertexVector : public VectorVertex<N> {
 public:
  static_assert(N >= 1 && N <= 9, "VertexVector is registered for 1 to 9 parameters");
  static constexpr const char kTags[9][8] = {"VECTOR1", "VECTOR2", "VECTOR3", "VECTOR4", "VECTOR5",
                                             "VECTOR6", "VECTOR7", "VECTOR8", "VECTOR9"};
  static constexpr const char* kTypeTag = kTags[N - 1];

  using VectorVertex<N>::VectorVertex;
  const char* typeTag() const override { return kTypeTag; }
  std::unique_ptr<Vertex> clone() const override { return std::make_unique<VertexVector>(*this); }
};

}  // namespace lrsvo
