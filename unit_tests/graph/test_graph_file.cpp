// Graph file round trips: save -> load -> save is exact for every vertex and
// edge type, information matrices, robust kernels and edge parameters.

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "lrsvo/edges/edge_bal_projection.h"
#include "lrsvo/edges/edge_types.h"
#include "lrsvo/graph/graph_file.h"
#include "lrsvo/graph/optimizer.h"
#include "unit_tests/graph/test_problems.h"

namespace lrsvo::test {
namespace {

// Euclidean vertices only (BAL cameras, points, a scale), least-squares edges
// with non-identity information and every kernel, a cost edge, fixed and
// non-marginalised flags.
Graph makeEuclideanGraph() {
  BalToyOptions bal;
  bal.cameras = 4;
  bal.points = 12;
  bal.fixedCameras = 1;
  bal.randomInformation = true;
  bal.kernel = "cycle";
  bal.kernelDelta = 1.75;
  Graph graph = makeBalToyProblem(bal);
  auto* point = static_cast<VertexPoint3*>(graph.vertex(5));
  point->setMarginalized(false);
  auto* scale = graph.addVertex(std::make_unique<VertexFocalScale>(100));
  scale->setEstimateVector(Eigen::Matrix<double, 1, 1>(0.1 / 3.0));
  auto cost = std::make_unique<EdgeQuadraticCost>();
  cost->setVertex(0, point);
  cost->setVertex(1, scale);
  cost->weight = Eigen::Matrix4d::Identity() / 7.0;
  cost->weight(0, 3) = cost->weight(3, 0) = 1.0 / 49.0;
  cost->centre = point->estimate().homogeneous() / 3.0;
  graph.addEdge(std::move(cost));
  return graph;
}

// The same plus poses and pinhole edges (with their focal parameter).
Graph makeMixedGraph() {
  Graph graph = makeEuclideanGraph();
  ToyOptions toy;
  toy.poses = 4;
  toy.points = 12;
  toy.sharedScale = true;
  toy.fixedPoses = 1;
  toy.randomInformation = true;
  toy.kernel = "cycle";
  toy.firstId = 200;
  addToyProblem(graph, toy);
  toy.sharedScale = false;
  toy.seed = 2;
  toy.firstId = 300;
  addToyProblem(graph, toy);
  return graph;
}

// The first line where two texts differ, or "" when they are equal.
std::string firstDifference(const std::string& a, const std::string& b) {
  std::istringstream inA(a), inB(b);
  std::string lineA, lineB;
  for (int line = 1;; ++line) {
    const bool moreA = static_cast<bool>(std::getline(inA, lineA));
    const bool moreB = static_cast<bool>(std::getline(inB, lineB));
    if (!moreA && !moreB) return "";
    if (moreA != moreB || lineA != lineB) return "line " + std::to_string(line) + ":\n  " + lineA + "\n  " + lineB;
  }
}

void expectExactRoundTrip(const Graph& original) {
  const std::string text = saveToString(original);
  const Graph loaded = loadFromString(text);
  EXPECT_EQ(firstDifference(text, saveToString(loaded)), "");
  ASSERT_EQ(loaded.vertices().size(), original.vertices().size());
  ASSERT_EQ(loaded.edges().size(), original.edges().size());
  for (std::size_t k = 0; k < original.vertices().size(); ++k) {
    const Vertex& a = *original.vertices()[k];
    const Vertex& b = *loaded.vertices()[k];
    EXPECT_EQ(a.id(), b.id());
    EXPECT_STREQ(a.typeTag(), b.typeTag());
    EXPECT_EQ(a.fixed(), b.fixed()) << a.id();
    EXPECT_EQ(a.marginalized(), b.marginalized()) << a.id();
  }
  // Bit for bit: compared as doubles with ==, not within a tolerance.
  const std::vector<double> a = original.estimates(), b = loaded.estimates();
  ASSERT_EQ(a.size(), b.size());
  int differing = 0;
  for (std::size_t k = 0; k < a.size(); ++k) differing += a[k] != b[k];
  EXPECT_EQ(differing, 0) << "estimate values that changed in the round trip";
  differing = 0;
  for (std::size_t k = 0; k < original.edges().size(); ++k) {
    EXPECT_STREQ(loaded.edges()[k]->typeTag(), original.edges()[k]->typeTag());
    differing += loaded.edges()[k]->cost() != original.edges()[k]->cost();
  }
  EXPECT_EQ(differing, 0) << "edge costs that changed in the round trip";
}

TEST(GraphFile, EuclideanGraphRoundTripsExactly) {
  const Graph graph = makeEuclideanGraph();
  const std::string text = saveToString(graph);
  for (const char* expected : {"BAL_CAMERA", "POINT3", "TEST_SCALE", "BAL_PROJECTION", "TEST_QUADRATIC", " Huber ",
                               " Cauchy ", " Tukey ", " NONE"})
    EXPECT_NE(text.find(expected), std::string::npos) << expected;
  expectExactRoundTrip(graph);
}

// VertexPose's estimate is (t, quaternion): the round trip must not drift
// through the rotation matrix it holds inside.
TEST(GraphFile, GraphWithPosesRoundTripsExactly) {
  const Graph graph = makeMixedGraph();
  const std::string text = saveToString(graph);
  for (const char* expected : {"POSE_SE3", "TEST_PINHOLE", "TEST_SCALED_PINHOLE"})
    EXPECT_NE(text.find(expected), std::string::npos) << expected;
  expectExactRoundTrip(graph);
}

TEST(GraphFile, LoadedEdgesKeepTheirData) {
  const Graph graph = makeMixedGraph();
  const Graph loaded = loadFromString(saveToString(graph));
  for (std::size_t k = 0; k < graph.edges().size(); ++k) {
    const auto* original = dynamic_cast<const EdgeBalProjection*>(graph.edges()[k].get());
    if (!original) continue;
    const auto* copy = dynamic_cast<const EdgeBalProjection*>(loaded.edges()[k].get());
    ASSERT_NE(copy, nullptr);
    EXPECT_EQ(copy->measurement(), original->measurement());
    EXPECT_EQ(copy->information(), original->information());
    ASSERT_EQ(copy->robustKernel() == nullptr, original->robustKernel() == nullptr);
    if (original->robustKernel()) {
      EXPECT_STREQ(copy->robustKernel()->name(), original->robustKernel()->name());
      EXPECT_EQ(copy->robustKernel()->delta(), original->robustKernel()->delta());
    }
  }
  int pinholes = 0;
  for (const auto& edge : loaded.edges())
    if (const auto* pinhole = dynamic_cast<const EdgeScaledPinhole*>(edge.get())) {
      EXPECT_EQ(pinhole->focal, 500.0);
      ++pinholes;
    }
  EXPECT_GT(pinholes, 0);
}

TEST(GraphFile, LoadedGraphOptimisesToTheSameCost) {
  Graph original = makeMixedGraph();
  Graph loaded = loadFromString(saveToString(original));
  EXPECT_NEAR(loaded.cost(), original.cost(), 1e-12 * original.cost());
  SolverOptions options;
  options.linearSolver = "schur_dense";
  const SolverSummary a = Optimizer(options).optimize(original);
  const SolverSummary b = Optimizer(options).optimize(loaded);
  EXPECT_LT(a.finalCost, 0.5 * a.initialCost);
  EXPECT_NEAR(b.initialCost, a.initialCost, 1e-12 * a.initialCost);
  EXPECT_NEAR(b.finalCost, a.finalCost, 1e-9 * a.finalCost);
}

TEST(GraphFile, FileOnDiskRoundTrips) {
  const Graph graph = makeEuclideanGraph();
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("lrsvo_test_graph_" + std::to_string(::getpid()) + ".graph");
  saveGraphFile(graph, path.string());
  registerEdgeTypes();
  const Graph loaded = loadGraphFile(path.string());
  std::filesystem::remove(path);
  EXPECT_EQ(firstDifference(saveToString(loaded), saveToString(graph)), "");
}

TEST(GraphFile, CommentsAndBlankLinesAreSkipped) {
  const Graph graph = makeEuclideanGraph();
  std::string text = saveToString(graph);
  text.insert(text.find("EDGE"), "\n   \n# a comment between vertices and edges\n");
  const Graph loaded = loadFromString(text);
  EXPECT_EQ(firstDifference(saveToString(loaded), saveToString(graph)), "");
}

}  // namespace
}  // namespace lrsvo::test
