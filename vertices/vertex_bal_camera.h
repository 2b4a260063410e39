#pragma once

#include "lrsvo/graph/vertex.h"

namespace lrsvo {

// A BAL (Snavely) camera: angle-axis rotation (3), translation (3), focal
// length f, radial distortion k1, k2, in that order, updated additively as
// the BAL data set and Ceres' BAL example do.
class VertexBalCamera : public VectorVertex<9> {
 public:
  static constexpr const char* kTypeTag = "BAL_CAMERA";
  using VectorVertex<9>::VectorVertex;
  const char* typeTag() const override { return kTypeTag; }
  std::unique_ptr<Vertex> clone() const override { return std::make_unique<VertexBalCamera>(*this); }
};

}  // namespace lrsvo
