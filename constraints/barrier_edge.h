#pragma once

#include "lrsvo/graph/edge.h"

namespace lrsvo {

// A unary log-barrier term on one parameter of a Euclidean vertex (docs/method.md,
// eq. 17-19): F = -mu log(1 - y^2), y = (x - centre) / halfWidth, i.e.
// -mu [log(x - b1) + log(b2 - x)] up to a constant that makes F zero at the
// centre. Exact gradient and Hessian; +inf outside the open box, so a trial
// step that leaves it is rejected.
class BarrierEdge : public Edge {
 public:
  static constexpr const char* kTypeTag = "BOUND_BARRIER";
  BarrierEdge() { vertices_.assign(1, nullptr); }
  BarrierEdge(Vertex* vertex, int index, double lower, double upper, double mu);

  // The barrier's weight, changed between the rounds of an interior-point schedule.
  void setMu(double mu) { mu_ = mu; }

  int vertexCount() const override { return 1; }
  const char* typeTag() const override { return kTypeTag; }
  bool acceptsVertex(int, const Vertex& vertex) const override { return vertex.isEuclidean(); }
  double cost() const override;
  double linearize() override;
  void addHessianBlock(int a, int b, double* block, int ld) const override;
  void addGradient(int a, double* gradient) const override;
  void writeData(std::ostream& out) const override;
  void readData(std::istream& in) override;

 private:
  double value() const;

  int index_ = 0;
  double lower_ = -1.0, upper_ = 1.0, mu_ = 1.0;
  double gradient_ = 0.0, hessian_ = 0.0;
};

}  // namespace lrsvo
