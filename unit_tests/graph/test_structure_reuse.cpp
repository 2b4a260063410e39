// An optimizer keeps the block structure and the symbolic analysis of its last
// solve: a graph of the same structure is solved on them again, exactly as a
// fresh optimizer would solve it, and any change of structure is set up afresh.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lrsvo/graph/error.h"
#include "lrsvo/graph/linear_solver.h"
#include "lrsvo/graph/optimizer.h"
#include "lrsvo/graph/registry.h"
#include "unit_tests/graph/test_problems.h"

namespace lrsvo::test {
namespace {

ToyOptions sharedScaleProblem() {
  ToyOptions options;
  options.poses = 5;
  options.points = 60;
  options.sharedScale = true;
  options.fixedPoses = 1;
  options.poseNoise = 0.05;
  options.pointNoise = 0.3;
  options.randomInformation = true;
  options.kernel = "cycle";
  options.outlierFraction = 0.1;
  return options;
}

Vertex* vertexOfType(const Graph& graph, const std::string& typeTag, int skip = 0) {
  for (const auto& vertex : graph.vertices())
    if (vertex->typeTag() == typeTag && skip-- == 0) return vertex.get();
  return nullptr;
}

TEST(StructureReuse, ASecondSolveOfTheSameStructureIsTheFreshSolveBitForBit) {
  for (const auto& [name, entry] : Registry<LinearSolver>::instance().entries()) {
    SCOPED_TRACE(name);
    SolverOptions options;
    options.linearSolver = name;
    options.maxIterations = 8;
    BalToyOptions problem;  // cameras coupled only through points, as every solver takes them
    problem.cameras = 6;
    problem.points = 150;
    problem.kernel = "cycle";
    Graph graph = makeBalToyProblem(problem);
    const std::vector<double> start = graph.estimates();

    Optimizer optimizer(options);
    const SolverSummary first = optimizer.optimize(graph);
    EXPECT_FALSE(first.structureReused);
    const std::vector<double> firstResult = graph.estimates();

    graph.setEstimates(start);
    const SolverSummary second = optimizer.optimize(graph);
    EXPECT_TRUE(second.structureReused);
    EXPECT_NE(second.fullReport().find("structure reused"), std::string::npos);
    EXPECT_EQ(graph.estimates(), firstResult);
    EXPECT_EQ(second.finalCost, first.finalCost);
    EXPECT_EQ(second.iterationCount(), first.iterationCount());
    // The phase times are this solve's, not the kept solver's running totals.
    EXPECT_LE(second.schurSeconds + second.factorizeSeconds, second.totalSeconds);
  }
}

// Each change of structure a user can make between two solves: the second
// solve sets up afresh and ends where a fresh optimizer ends on the same
// changed graph (and a change that leaves the system's structure as it was
// is solved on the kept one, to the same end).
TEST(StructureReuse, AnyChangeOfStructureIsSetUpAfresh) {
  const std::vector<std::pair<std::string, std::function<void(Graph&)>>> changes = {
      {"a free pose fixed", [](Graph& g) { vertexOfType(g, VertexPose::kTypeTag, 2)->setFixed(true); }},
      {"the fixed pose freed", [](Graph& g) { vertexOfType(g, VertexPose::kTypeTag, 0)->setFixed(false); }},
      {"a point no longer marginalised",
       [](Graph& g) { vertexOfType(g, VertexPoint3::kTypeTag, 3)->setMarginalized(false); }},
      {"an edge removed", [](Graph& g) { g.removeEdge(g.edges()[7].get()); }},
      {"an edge added",
       [](Graph& g) {
         auto edge = std::make_unique<EdgeQuadraticCost>();
         edge->setVertex(0, vertexOfType(g, VertexPoint3::kTypeTag, 5));
         edge->setVertex(1, vertexOfType(g, VertexFocalScale::kTypeTag));
         g.addEdge(std::move(edge));
       }},
      {"an edge moved to another point",
       [](Graph& g) {
         Edge* edge = g.edges()[4].get();
         for (int a = 0; a < edge->vertexCount(); ++a)
           if (edge->vertex(a)->typeTag() == std::string(VertexPoint3::kTypeTag))
             edge->setVertex(a, vertexOfType(g, VertexPoint3::kTypeTag, 40));
       }},
  };
  for (const char* solver : {"lm_schur_cholmod", "lm_schur_dense", "lm_cholmod"}) {
    for (const auto& [what, change] : changes) {
      SCOPED_TRACE(std::string(solver) + ", " + what);
      Optimizer kept(SolverOptions::fromName(solver));
      Graph graph = makeToyProblem(sharedScaleProblem());
      const std::vector<double> start = graph.estimates();
      kept.optimize(graph);
      graph.setEstimates(start);
      change(graph);
      const SolverSummary again = kept.optimize(graph);
      // Without the Schur ordering, whether a vertex is marginalised does not shape the system.
      const bool sameStructure = what == "a point no longer marginalised" && std::string(solver) == "lm_cholmod";
      EXPECT_EQ(again.structureReused, sameStructure);

      Graph fresh = makeToyProblem(sharedScaleProblem());
      change(fresh);
      const SolverSummary reference = Optimizer(SolverOptions::fromName(solver)).optimize(fresh);
      EXPECT_EQ(graph.estimates(), fresh.estimates());
      EXPECT_EQ(again.finalCost, reference.finalCost);
    }
  }
}

// A start to come back to: every estimate in vertex order, set back exactly;
// a list of another length is refused.
TEST(GraphEstimates, ComeBackThroughSetEstimates) {
  Graph graph = makeToyProblem(sharedScaleProblem());
  const std::vector<double> start = graph.estimates();
  std::size_t expected = 0;
  for (const auto& vertex : graph.vertices()) expected += static_cast<std::size_t>(vertex->estimateSize());
  ASSERT_EQ(start.size(), expected);
  Optimizer().optimize(graph);
  ASSERT_NE(graph.estimates(), start);
  graph.setEstimates(start);
  EXPECT_EQ(graph.estimates(), start);
  EXPECT_THROW(graph.setEstimates(std::vector<double>(start.begin(), start.end() - 1)), Error);
}

// Another graph of the same shape is a different structure (its vertices and
// edges are other objects); releaseStructure() forgets the kept one.
TEST(StructureReuse, AnotherGraphOrAReleasedStructureIsSetUpAfresh) {
  Optimizer optimizer;
  Graph one = makeToyProblem(sharedScaleProblem());
  Graph two = makeToyProblem(sharedScaleProblem());
  EXPECT_FALSE(optimizer.optimize(one).structureReused);
  EXPECT_FALSE(optimizer.optimize(two).structureReused);
  EXPECT_TRUE(optimizer.optimize(two).structureReused);
  optimizer.releaseStructure();
  EXPECT_FALSE(optimizer.optimize(two).structureReused);
  // A copy takes the options only.
  Optimizer copy(optimizer);
  EXPECT_FALSE(copy.optimize(two).structureReused);
  EXPECT_TRUE(optimizer.optimize(two).structureReused);
}

}  // namespace
}  // namespace lrsvo::test
