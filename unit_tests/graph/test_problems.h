#pragma once

// Seeded toy problems and checks shared by the framework's unit tests. The
// vertex and edge types here are defined the way a user of the library would
// add their own, so they also exercise that path (registry, graph file).

#include <cstdint>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Core>

#include "lrsvo/graph/base_cost_edge.h"
#include "lrsvo/graph/base_edge.h"
#include "lrsvo/graph/block_system.h"
#include "lrsvo/graph/graph.h"
#include "lrsvo/vertices/vertex_point3.h"
#include "lrsvo/vertices/vertex_pose.h"

namespace lrsvo::test {

// One scalar shared by every observation of a problem (a focal-length
// scale), coupling all poses as the stereo extrinsic or kappa do.
class VertexFocalScale : public VectorVertex<1> {
 public:
  static constexpr const char* kTypeTag = "TEST_SCALE";
  using VectorVertex<1>::VectorVertex;
  const char* typeTag() const override { return kTypeTag; }
  std::unique_ptr<Vertex> clone() const override { return std::make_unique<VertexFocalScale>(*this); }
};

// Pinhole projection of a world point through a camera-from-world pose:
// X_c = R X + t, prediction f X_c.xy / X_c.z. Analytic Jacobians.
class EdgePinhole : public BaseEdge<2, VertexPose, VertexPoint3> {
 public:
  static constexpr const char* kTypeTag = "TEST_PINHOLE";
  const char* typeTag() const override { return kTypeTag; }
  double focal = 500.0;
  void computeResidual(Residual& residual) const override;
  void computeJacobians() override;

 protected:
  void writeParameters(std::ostream& out) const override;
  void readParameters(std::istream& in) override;
};

// The same with a shared scale s on the focal length: f (1 + s) X_c.xy / X_c.z.
class EdgeScaledPinhole : public BaseEdge<2, VertexPose, VertexPoint3, VertexFocalScale> {
 public:
  static constexpr const char* kTypeTag = "TEST_SCALED_PINHOLE";
  const char* typeTag() const override { return kTypeTag; }
  double focal = 500.0;
  void computeResidual(Residual& residual) const override;
  void computeJacobians() override;

 protected:
  void writeParameters(std::ostream& out) const override;
  void readParameters(std::istream& in) override;
};

// A cost edge 1/2 (x - c)^T A (x - c) on x = (point, scale) stacked.
class EdgeQuadraticCost : public BaseCostEdge<VertexPoint3, VertexFocalScale> {
 public:
  static constexpr const char* kTypeTag = "TEST_QUADRATIC";
  const char* typeTag() const override { return kTypeTag; }
  Hessian weight = Hessian::Identity();
  Gradient centre = Gradient::Zero();
  double cost() const override;
  void computeGradientHessian(Gradient& gradient, Hessian& hessian) const override;
  void writeData(std::ostream& out) const override;
  void readData(std::istream& in) override;

 private:
  Gradient stacked() const;
};

// Poses looking at a cloud of points, each point seen by a band of
// consecutive poses (so not every pair of poses is co-visible).
// Vertex ids: poses firstId.., points after them, the scale (if any) last.
struct ToyOptions {
  int poses = 6;
  int points = 40;
  int posesPerPoint = 3;
  bool sharedScale = false;  // observations are EdgeScaledPinhole on one VertexFocalScale
  int fixedPoses = 2;        // the first poses are held fixed (fixes the gauge)
  int fixedPoints = 0;       // the first points are held fixed
  double pixelNoise = 0.5;
  double outlierFraction = 0.0;  // observations moved by ~30 pixels
  double poseNoise = 0.02;       // start perturbation, rad and m
  double pointNoise = 0.1;       // m
  double scaleNoise = 0.01;
  bool randomInformation = false;  // non-identity information matrices
  std::string kernel;              // "" for none, "cycle" for Huber, Cauchy, Tukey, none in turn
  double kernelDelta = 2.0;
  int firstId = 0;
  std::uint64_t seed = 1;
};
// Adds the problem to the graph; returns the next unused vertex id.
int addToyProblem(Graph& graph, const ToyOptions& options);
Graph makeToyProblem(const ToyOptions& options);

// BAL cameras (angle-axis, t, f, k1, k2) looking at points, EdgeBalProjection.
struct BalToyOptions {
  int cameras = 4;
  int points = 30;
  int camerasPerPoint = 3;
  int fixedCameras = 1;
  double pixelNoise = 0.5;
  bool randomInformation = false;
  std::string kernel;  // as ToyOptions::kernel
  double kernelDelta = 2.0;
  int firstId = 0;
  std::uint64_t seed = 1;
};
int addBalToyProblem(Graph& graph, const BalToyOptions& options);
Graph makeBalToyProblem(const BalToyOptions& options);

// The system's H (with its current diagonal shift) as a dense symmetric matrix.
Eigen::MatrixXd denseHessian(const BlockSystem& system);

// Text of saveGraph / the graph of loadGraph, through strings.
std::string saveToString(const Graph& graph);
Graph loadFromString(const std::string& text, const std::string& sourceName = "test.graph");

namespace detail {

template <int K, typename EdgeType>
void compareJacobian(const EdgeType& edge, const Eigen::MatrixXd& analytic, double relative, double absolute,
                     const char* referenceName, std::string& failures) {
  if (edge.vertex(K)->fixed()) return;
  const auto& reference = edge.template jacobian<K>();
  for (Eigen::Index c = 0; c < reference.cols(); ++c) {
    const double error = (analytic.col(c) - reference.col(c)).norm();
    if (error <= relative * reference.col(c).norm() + absolute) continue;
    std::ostringstream out;
    out.precision(17);
    out << "vertex " << K << " column " << c << ": analytic " << analytic.col(c).transpose() << ", " << referenceName
        << " " << reference.col(c).transpose() << " (error " << error << ")\n";
    failures += out.str();
  }
}

// Runs computeJacobians() (analytic), then `reference` on the same edge, and compares.
template <typename EdgeType, typename Reference, std::size_t... K>
::testing::AssertionResult compareJacobians(EdgeType& edge, Reference reference, const char* referenceName,
                                            double relative, double absolute, std::index_sequence<K...>) {
  edge.computeJacobians();
  const std::tuple analytic{Eigen::MatrixXd(edge.template jacobian<static_cast<int>(K)>())...};
  reference(edge);
  std::string failures;
  (compareJacobian<static_cast<int>(K)>(edge, std::get<K>(analytic), relative, absolute, referenceName, failures), ...);
  if (failures.empty()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << edge.typeTag() << " Jacobians differ from " << referenceName << ":\n"
                                       << failures;
}

}  // namespace detail

// Compares jacobian<K>() after computeJacobians() (analytic) with
// computeNumericJacobians() for every non-fixed vertex K, column by column:
// |analytic - numeric| <= relative |numeric| + absolute.
template <typename EdgeType>
::testing::AssertionResult jacobiansMatchNumeric(EdgeType& edge, double relative = 1e-6, double absolute = 1e-6) {
  return detail::compareJacobians(
      edge, [](EdgeType& e) { e.computeNumericJacobians(); }, "central differences", relative, absolute,
      std::make_index_sequence<EdgeType::kVertexCount>{});
}

// The same against computeAutoDiffJacobians() (graph/autodiff_edge.h).
template <typename EdgeType>
::testing::AssertionResult jacobiansMatchAutoDiff(EdgeType& edge, double relative, double absolute) {
  return detail::compareJacobians(
      edge, [](EdgeType& e) { e.computeAutoDiffJacobians(); }, "automatic differentiation", relative, absolute,
      std::make_index_sequence<EdgeType::kVertexCount>{});
}

}  // namespace lrsvo::test
