#pragma once

#include "lrsvo/graph/vertex.h"

namespace lrsvo {

// A 3-D point in world coordinates; marginalised by default (eliminated by
// the Schur complement in bundle adjustment).
class VertexPoint3 : public VectorVertex<3> {
 public:
  static constexpr const char* kTypeTag = "POINT3";
  explicit VertexPoint3(int id = -1, const Eigen::Vector3d& position = Eigen::Vector3d::Zero());
  const char* typeTag() const override { return kTypeTag; }
  std::unique_ptr<Vertex> clone() const override { return std::make_unique<VertexPoint3>(*this); }
};

}  // namespace lrsvo
