#pragma once

#include "lrsvo/graph/vertex.h"

namespace lrsvo {

// The scale kappa of a monocular start (docs/method.md, eq. 5): the metric
// baseline c measures c / kappa in the map's arbitrary unit, so kappa is the
// map's metric scale (docs/method.md, long-range initialisation, step 5).
// Must stay positive; edges reading it give a non-finite residual otherwise,
// so a step through zero is rejected.
class VertexScale : public VectorVertex<1> {
 public:
  static constexpr const char* kTypeTag = "SCALE";
  explicit VertexScale(int id = -1, double kappa = 1.0);
  double kappa() const { return estimate_[0]; }
  const char* typeTag() const override { return kTypeTag; }
  std::unique_ptr<Vertex> clone() const override { return std::make_unique<VertexScale>(*this); }
};

}  // namespace lrsvo
