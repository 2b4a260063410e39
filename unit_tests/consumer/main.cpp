// Uses the installed lrsvo as a library: defines its own edge type on lrsvo's
// vertices, builds a two-vertex graph and optimises it. Exits non-zero unless
// the cost drops and the free point reaches the measured offset.
#include <cstdio>
#include <memory>

#include <Eigen/Core>

#include "lrsvo/graph/base_edge.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/graph.h"
#include "lrsvo/graph/optimizer.h"
#include "lrsvo/vertices/vertex_point3.h"

namespace {

// The user's own type: a measured offset from the first point to the second.
class EdgePointOffset : public lrsvo::BaseEdge<3, lrsvo::VertexPoint3, lrsvo::VertexPoint3> {
 public:
  static constexpr const char* kTypeTag = "CONSUMER_POINT_OFFSET";
  const char* typeTag() const override { return kTypeTag; }

  void computeResidual(Residual& residual) const override {
    residual = vertexAs<1>()->estimate() - vertexAs<0>()->estimate() - measurement();
  }
  void computeJacobians() override {
    jacobian<0>() = -Eigen::Matrix3d::Identity();
    jacobian<1>() = Eigen::Matrix3d::Identity();
  }
};

}  // namespace

int main() {
  try {
    const Eigen::Vector3d anchorPosition(1.0, -2.0, 0.5);
    const Eigen::Vector3d offset(0.3, 0.4, -1.2);

    lrsvo::Graph graph;
    auto* anchor = graph.addVertex(std::make_unique<lrsvo::VertexPoint3>(0, anchorPosition));
    anchor->setFixed(true);
    auto* point = graph.addVertex(std::make_unique<lrsvo::VertexPoint3>(1, Eigen::Vector3d(4.0, 2.0, -3.0)));

    auto edge = std::make_unique<EdgePointOffset>();
    edge->setVertex(0, anchor);
    edge->setVertex(1, point);
    edge->setMeasurement(offset);
    edge->setInformation(4.0 * Eigen::Matrix3d::Identity());
    graph.addEdge(std::move(edge));

    const lrsvo::SolverSummary summary = lrsvo::Optimizer(lrsvo::SolverOptions::fromName("lm_dense")).optimize(graph);
    std::printf("%s\n", summary.briefReport().c_str());

    const double error = (point->estimate() - (anchorPosition + offset)).norm();
    if (!(summary.finalCost < summary.initialCost) || !(error < 1e-6)) {
      std::fprintf(stderr, "consumer: the optimisation failed: cost %g -> %g, point off by %g\n", summary.initialCost,
                   summary.finalCost, error);
      return 1;
    }
    return 0;
  } catch (const lrsvo::Error& e) {
    std::fprintf(stderr, "consumer: error: %s\n", e.what());
    return 1;
  }
}
