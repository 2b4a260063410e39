// Uses lrsvo's graph library alone: its own parameter vertex and one edge per
// observation fit y = a exp(b x) to exact samples, with the dense and the
// CHOLMOD solver. Exits non-zero unless both recover a and b.
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include <Eigen/Core>

#include "lrsvo/graph/base_edge.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/graph.h"
#include "lrsvo/graph/optimizer.h"
#include "lrsvo/graph/vertex.h"

namespace {

class VertexCurve : public lrsvo::VectorVertex<2> {
 public:
  static constexpr const char* kTypeTag = "CONSUMER_CURVE";
  using VectorVertex<2>::VectorVertex;
  const char* typeTag() const override { return kTypeTag; }
  std::unique_ptr<lrsvo::Vertex> clone() const override { return std::make_unique<VertexCurve>(*this); }
};

// The residual a exp(b x) - y of one sample (x, y); the measurement is y.
class EdgeCurveSample : public lrsvo::BaseEdge<1, VertexCurve> {
 public:
  static constexpr const char* kTypeTag = "CONSUMER_CURVE_SAMPLE";
  explicit EdgeCurveSample(double x = 0.0) : x_(x) {}
  const char* typeTag() const override { return kTypeTag; }

  void computeResidual(Residual& residual) const override {
    const Eigen::Vector2d& p = vertexAs<0>()->estimate();
    residual[0] = p[0] * std::exp(p[1] * x_) - measurement()[0];
  }
  void computeJacobians() override {
    const Eigen::Vector2d& p = vertexAs<0>()->estimate();
    const double e = std::exp(p[1] * x_);
    jacobian<0>() << e, p[0] * x_ * e;
  }

 private:
  double x_;
};

bool fits(const std::string& solver) {
  const double a = 2.5, b = -0.7;
  lrsvo::Graph graph;
  auto* curve = graph.addVertex(std::make_unique<VertexCurve>(0));
  curve->setEstimateVector(Eigen::Vector2d(1.0, 0.0));
  for (int i = 0; i < 20; ++i) {
    const double x = 0.2 * i;
    auto edge = std::make_unique<EdgeCurveSample>(x);
    edge->setVertex(0, curve);
    edge->setMeasurement(Eigen::Matrix<double, 1, 1>(a * std::exp(b * x)));
    graph.addEdge(std::move(edge));
  }
  const lrsvo::SolverSummary summary = lrsvo::Optimizer(lrsvo::SolverOptions::fromName(solver)).optimize(graph);
  std::printf("%s: %s\n", solver.c_str(), summary.briefReport().c_str());
  // Exact samples: the solver's gradient tolerance leaves errors far below 1e-6.
  return std::abs(curve->estimate()[0] - a) < 1e-6 && std::abs(curve->estimate()[1] - b) < 1e-6;
}

}  // namespace

int main() {
  try {
    for (const char* solver : {"lm_dense", "lm_cholmod"}) {
      if (!fits(solver)) {
        std::fprintf(stderr, "graph consumer: %s did not recover the curve\n", solver);
        return 1;
      }
    }
    return 0;
  } catch (const lrsvo::Error& e) {
    std::fprintf(stderr, "graph consumer: error: %s\n", e.what());
    return 1;
  }
}
