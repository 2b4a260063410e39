// Bad input through the graph file and the API: each gets an lrsvo::Error
// (ParseError with the right line for files) naming the place, never a crash.

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "lrsvo/graph/error.h"
#include "lrsvo/graph/graph_file.h"
#include "lrsvo/graph/optimizer.h"
#include "lrsvo/vertices/vertex_bal_camera.h"
#include "unit_tests/graph/test_problems.h"

namespace lrsvo::test {
namespace {

constexpr const char* kSource = "window_17.graph";

// A small valid file, as lines: header, 3 poses, 4 points, 8 edges, END.
std::vector<std::string> validLines() {
  ToyOptions options;
  options.poses = 3;
  options.points = 4;
  options.posesPerPoint = 2;
  options.fixedPoses = 1;
  options.randomInformation = true;
  options.kernel = "cycle";
  std::istringstream in(saveToString(makeToyProblem(options)));
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string join(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += line + '\n';
  return text;
}

// 1-based number of the first line starting with `prefix`.
int lineStarting(const std::vector<std::string>& lines, const std::string& prefix) {
  for (std::size_t k = 0; k < lines.size(); ++k)
    if (lines[k].rfind(prefix, 0) == 0) return static_cast<int>(k) + 1;
  ADD_FAILURE() << "no line starts with " << prefix;
  return 0;
}

// Replaces whitespace-separated token `index` of the 1-based line.
void replaceToken(std::vector<std::string>& lines, int line, int index, const std::string& value) {
  std::istringstream in(lines[line - 1]);
  std::vector<std::string> tokens;
  for (std::string token; in >> token;) tokens.push_back(token);
  ASSERT_LT(index, static_cast<int>(tokens.size()));
  tokens[index] = value;
  std::string joined;
  for (const std::string& token : tokens) joined += (joined.empty() ? "" : " ") + token;
  lines[line - 1] = joined;
}

::testing::AssertionResult failsAtLine(const std::string& text, int line, const std::string& fragment = "") {
  try {
    loadFromString(text, kSource);
  } catch (const ParseError& error) {
    const std::string what = error.what();
    const std::string place = std::string(kSource) + ":" + std::to_string(line) + ":";
    if (error.line() != line || error.file() != kSource || what.find(place) == std::string::npos)
      return ::testing::AssertionFailure() << "expected an error at " << place << ", got: " << what;
    if (what.find(fragment) == std::string::npos)
      return ::testing::AssertionFailure() << "message lacks '" << fragment << "': " << what;
    return ::testing::AssertionSuccess();
  } catch (const std::exception& error) {
    return ::testing::AssertionFailure() << "not a ParseError: " << error.what();
  }
  return ::testing::AssertionFailure() << "loaded without an error";
}

TEST(BadGraphFile, TheUnmodifiedFileLoads) {
  const std::vector<std::string> lines = validLines();
  ASSERT_EQ(lines.size(), 17u);
  const Graph graph = loadFromString(join(lines));
  EXPECT_EQ(graph.vertices().size(), 7u);
  EXPECT_EQ(graph.edges().size(), 8u);
  EXPECT_GT(graph.cost(), 0.0);
}

TEST(BadGraphFile, MalformedNumbers) {
  const std::vector<std::string> valid = validLines();
  const int point = lineStarting(valid, "VERTEX POINT3");
  const int edge = lineStarting(valid, "EDGE");
  // (line, token, value): a coordinate, an id, a flag, a measurement, information, kernel delta.
  const std::vector<std::tuple<int, int, std::string>> cases = {
      {point, 5, "abc"}, {point, 6, "1.5e"}, {point, 2, "x7"},   {point, 3, "yes"},
      {edge, 5, "-"},    {edge, 6, "1,5"},   {edge, 9, "0x1p+"}, {edge, 3, "3.5.1"}};
  for (const auto& [line, token, value] : cases) {
    std::vector<std::string> lines = valid;
    replaceToken(lines, line, token, value);
    EXPECT_TRUE(failsAtLine(join(lines), line)) << "token " << token << " = " << value;
  }
}

TEST(BadGraphFile, NonFiniteValues) {
  const std::vector<std::string> valid = validLines();
  const int pose = lineStarting(valid, "VERTEX POSE_SE3");
  const int edge = lineStarting(valid, "EDGE");
  for (const char* value : {"nan", "NaN", "inf", "-inf", "1e999", "-1e400"}) {
    for (const auto& [line, token] : {std::pair{pose, 5}, std::pair{edge, 6}, std::pair{edge, 8}}) {
      std::vector<std::string> lines = valid;
      replaceToken(lines, line, token, value);
      EXPECT_TRUE(failsAtLine(join(lines), line)) << "token " << token << " = " << value;
    }
  }
}

TEST(BadGraphFile, MissingEndLine) {
  std::vector<std::string> lines = validLines();
  lines.pop_back();
  // The error is where the END line should have been.
  EXPECT_TRUE(failsAtLine(join(lines), static_cast<int>(lines.size()) + 1, "END"));
}

TEST(BadGraphFile, FileCutInTheMiddleOfALine) {
  const std::vector<std::string> valid = validLines();
  for (const char* prefix : {"VERTEX POINT3", "EDGE"}) {
    const int line = lineStarting(valid, prefix);
    std::vector<std::string> lines(valid.begin(), valid.begin() + line);
    lines.back().resize(lines.back().size() / 2);
    std::string text = join(lines);
    text.pop_back();  // no final newline, as when a write was interrupted
    EXPECT_TRUE(failsAtLine(text, line)) << prefix;
  }
}

TEST(BadGraphFile, EdgeNamingAMissingVertex) {
  std::vector<std::string> lines = validLines();
  const int edge = lineStarting(lines, "EDGE");
  replaceToken(lines, edge, 3, "999");
  EXPECT_TRUE(failsAtLine(join(lines), edge, "999"));
}

TEST(BadGraphFile, DuplicateVertexId) {
  std::vector<std::string> lines = validLines();
  const int point = lineStarting(lines, "VERTEX POINT3");
  lines.insert(lines.begin() + point, lines[point - 1]);
  EXPECT_TRUE(failsAtLine(join(lines), point + 1, "duplicate"));
}

TEST(BadGraphFile, UnknownTypeTagsAndKeywords) {
  const std::vector<std::string> valid = validLines();
  const int point = lineStarting(valid, "VERTEX POINT3");
  const int edge = lineStarting(valid, "EDGE");
  std::vector<std::string> lines = valid;
  replaceToken(lines, point, 1, "POINT4");
  EXPECT_TRUE(failsAtLine(join(lines), point, "POINT4"));
  EXPECT_TRUE(failsAtLine(join(lines), point, "POINT3")) << "the message should list the known tags";
  lines = valid;
  replaceToken(lines, edge, 1, "NO_SUCH_EDGE");
  EXPECT_TRUE(failsAtLine(join(lines), edge, "NO_SUCH_EDGE"));
  lines = valid;
  replaceToken(lines, edge, 0, "EDGES");
  EXPECT_TRUE(failsAtLine(join(lines), edge, "EDGES"));
  lines = valid;
  replaceToken(lines, edge, 10, "Welsch");  // the first edge's kernel name (Huber)
  EXPECT_TRUE(failsAtLine(join(lines), edge, "Welsch"));
}

TEST(BadGraphFile, TrailingGarbage) {
  const std::vector<std::string> valid = validLines();
  for (const char* prefix : {"VERTEX POSE_SE3", "EDGE", "END"}) {
    std::vector<std::string> lines = valid;
    const int line = lineStarting(lines, prefix);
    lines[line - 1] += " 42";
    EXPECT_TRUE(failsAtLine(join(lines), line, "42")) << prefix;
  }
  std::vector<std::string> lines = valid;
  lines.push_back(valid[1]);
  EXPECT_TRUE(failsAtLine(join(lines), static_cast<int>(lines.size()), "after the END"));
}

TEST(BadGraphFile, EndCountsThatDoNotMatch) {
  std::vector<std::string> lines = validLines();
  replaceToken(lines, static_cast<int>(lines.size()), 2, "9");
  EXPECT_TRUE(failsAtLine(join(lines), static_cast<int>(lines.size())));
}

TEST(BadGraphFile, InvalidValues) {
  const std::vector<std::string> valid = validLines();
  const int pose = lineStarting(valid, "VERTEX POSE_SE3");
  const int edge = lineStarting(valid, "EDGE");
  std::vector<std::string> lines = valid;
  replaceToken(lines, pose, 11, "2");  // quaternion w: not a unit quaternion
  EXPECT_TRUE(failsAtLine(join(lines), pose, "quaternion"));
  // Information upper triangle (tokens 7, 8, 9 after tag, 2 ids, focal, 2 measurements): indefinite.
  lines = valid;
  replaceToken(lines, edge, 7, "1");
  replaceToken(lines, edge, 8, "2");
  replaceToken(lines, edge, 9, "1");
  EXPECT_TRUE(failsAtLine(join(lines), edge, "positive definite"));
  lines = valid;
  replaceToken(lines, edge, 11, "-1");  // Huber delta
  EXPECT_TRUE(failsAtLine(join(lines), edge, "delta"));
  lines = valid;
  replaceToken(lines, edge, 4, "-500");  // focal length
  EXPECT_TRUE(failsAtLine(join(lines), edge, "focal"));
}

// A BAL projection whose camera slot names a pose: the types do not fit.
TEST(BadGraphFile, EdgeNamingAVertexOfTheWrongType) {
  std::vector<std::string> lines = validLines();
  const int edge = lineStarting(lines, "EDGE");
  std::istringstream in(lines[edge - 1]);
  std::string keyword, tag, pose, point;
  in >> keyword >> tag >> pose >> point;
  lines[edge - 1] = "EDGE BAL_PROJECTION " + pose + " " + point + " 1 2 1 0 1 NONE";
  EXPECT_TRUE(failsAtLine(join(lines), edge, pose));
}

TEST(BadGraphFile, MissingFileIsNamed) {
  try {
    loadGraphFile("/nonexistent/dir/window.graph");
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/dir/window.graph"), std::string::npos);
  }
}

// Runs the optimiser expecting an lrsvo::Error whose message contains every fragment.
::testing::AssertionResult optimizeFailsWith(Graph& graph, const std::vector<std::string>& fragments,
                                             SolverOptions options = {}) {
  try {
    Optimizer(options).optimize(graph);
  } catch (const Error& error) {
    for (const std::string& fragment : fragments)
      if (std::string(error.what()).find(fragment) == std::string::npos)
        return ::testing::AssertionFailure() << "message lacks '" << fragment << "': " << error.what();
    return ::testing::AssertionSuccess();
  } catch (const std::exception& error) {
    return ::testing::AssertionFailure() << "not an lrsvo::Error: " << error.what();
  }
  return ::testing::AssertionFailure() << "optimised without an error";
}

TEST(BadApiInput, EmptyGraphAndGraphWithoutEdges) {
  Graph empty;
  EXPECT_TRUE(optimizeFailsWith(empty, {"no vertices"}));
  Graph noEdges;
  noEdges.addVertex(std::make_unique<VertexPoint3>(1));
  EXPECT_TRUE(optimizeFailsWith(noEdges, {"no edges"}));
}

TEST(BadApiInput, EverythingFixed) {
  ToyOptions options;
  options.fixedPoses = options.poses;
  options.fixedPoints = options.points;
  Graph graph = makeToyProblem(options);
  EXPECT_TRUE(optimizeFailsWith(graph, {"fixed"}));
}

TEST(BadApiInput, NonFiniteEstimateNamesTheVertex) {
  for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    Graph graph = makeToyProblem({});
    auto* point = static_cast<VertexPoint3*>(graph.vertex(9));
    point->setEstimateVector(Eigen::Vector3d(0.0, bad, 1.0));
    EXPECT_TRUE(optimizeFailsWith(graph, {"vertex 9", "POINT3"}));
  }
}

TEST(BadApiInput, NonFiniteStartCostNamesTheEdge) {
  Graph graph = makeToyProblem({});
  // Move point 9 onto the image plane z = 0 of the first pose that sees it.
  const Edge* seeing = nullptr;
  for (const auto& edge : graph.edges())
    if (!seeing && edge->vertex(1)->id() == 9) seeing = edge.get();
  ASSERT_NE(seeing, nullptr);
  const auto* pose = static_cast<const VertexPose*>(seeing->vertex(0));
  auto* point = static_cast<VertexPoint3*>(graph.vertex(9));
  point->setEstimateVector(pose->cameraFromWorld().inverse() * Eigen::Vector3d(1.0, 1.0, 0.0));
  EXPECT_TRUE(optimizeFailsWith(graph, {"TEST_PINHOLE", std::to_string(pose->id()) + " 9"}));
}

TEST(BadApiInput, InformationMustBeSymmetricPositiveDefinite) {
  EdgePinhole edge;
  Eigen::Matrix2d indefinite;
  indefinite << 1, 2, 2, 1;
  Eigen::Matrix2d asymmetric;
  asymmetric << 1, 0.5, 0, 1;
  Eigen::Matrix2d nan = Eigen::Matrix2d::Identity();
  nan(1, 1) = std::numeric_limits<double>::quiet_NaN();
  for (const Eigen::Matrix2d& bad : {indefinite, asymmetric, nan, Eigen::Matrix2d::Zero().eval()})
    EXPECT_THROW(edge.setInformation(bad), Error) << bad;
  EXPECT_EQ(edge.information(), Eigen::Matrix2d::Identity());
}

TEST(BadApiInput, UnknownSolverNamesListTheKnownOnes) {
  const std::vector<std::string> linearSolvers = {"dense", "cholmod", "schur_dense", "schur_cholmod"};
  auto messageOf = [](auto&& call) -> std::string {
    try {
      call();
    } catch (const Error& error) {
      return error.what();
    }
    return "";
  };
  const std::string badLinear = messageOf([] { SolverOptions::fromName("lm_qr"); });
  const std::string badAlgorithm = messageOf([] { SolverOptions::fromName("dogleg_dense"); });
  const std::string noSeparator = messageOf([] { SolverOptions::fromName("lm"); });
  Graph graph = makeToyProblem({});
  SolverOptions options;
  options.linearSolver = "qr";
  const std::string atOptimize = messageOf([&] { Optimizer(options).optimize(graph); });
  for (const std::string& message : {badLinear, atOptimize}) {
    EXPECT_NE(message.find("qr"), std::string::npos) << message;
    for (const std::string& name : linearSolvers) EXPECT_NE(message.find(name), std::string::npos) << message;
  }
  EXPECT_NE(badAlgorithm.find("dogleg"), std::string::npos) << badAlgorithm;
  EXPECT_NE(badAlgorithm.find("gn"), std::string::npos) << badAlgorithm;
  EXPECT_NE(badAlgorithm.find("lm"), std::string::npos) << badAlgorithm;
  EXPECT_FALSE(noSeparator.empty());
}

TEST(BadApiInput, InvalidSolverOptions) {
  SolverOptions options;
  options.threads = 0;
  EXPECT_THROW(Optimizer{options}, Error);
  options = {};
  options.maxIterations = -1;
  EXPECT_THROW(Optimizer{options}, Error);
}

TEST(BadApiInput, GraphRejectsBadVerticesAndEdges) {
  Graph graph;
  auto* a = graph.addVertex(std::make_unique<VertexPose>(1));
  auto* b = graph.addVertex(std::make_unique<VertexPoint3>(2));
  EXPECT_THROW(graph.addVertex(std::make_unique<VertexPoint3>(2)), Error);
  EXPECT_THROW(graph.addVertex(std::unique_ptr<Vertex>()), Error);

  VertexPoint3 outsider(3);
  auto edge = std::make_unique<EdgePinhole>();
  edge->setVertex(0, a);
  edge->setVertex(1, &outsider);
  EXPECT_THROW(graph.addEdge(std::move(edge)), Error);

  VertexPoint3 sameIdOutsider(2);  // same id as b, but not b
  edge = std::make_unique<EdgePinhole>();
  edge->setVertex(0, a);
  edge->setVertex(1, &sameIdOutsider);
  EXPECT_THROW(graph.addEdge(std::move(edge)), Error);

  edge = std::make_unique<EdgePinhole>();
  edge->setVertex(0, a);
  EXPECT_THROW(graph.addEdge(std::move(edge)), Error);
  EXPECT_TRUE(graph.edges().empty());

  edge = std::make_unique<EdgePinhole>();
  edge->setVertex(0, a);
  edge->setVertex(1, b);
  EXPECT_NO_THROW(graph.addEdge(std::move(edge)));
  EXPECT_EQ(graph.edges().size(), 1u);
}

// The vertex slots of an edge are typed; a vertex of another type must be
// refused when the edge is added, not read as the wrong type later.
TEST(BadApiInput, GraphRejectsAnEdgeOnAVertexOfTheWrongType) {
  Graph graph;
  auto* camera = graph.addVertex(std::make_unique<VertexBalCamera>(1));
  auto* point = graph.addVertex(std::make_unique<VertexPoint3>(2));
  auto edge = std::make_unique<EdgePinhole>();
  edge->setVertex(0, camera);  // EdgePinhole wants a VertexPose here
  edge->setVertex(1, point);
  EXPECT_THROW(graph.addEdge(std::move(edge)), Error);
}

// An edge between two marginalised vertices cannot be Schur-eliminated block
// by block: the Schur solvers must refuse, a full solver handles it.
class EdgePointDistance : public BaseEdge<3, VertexPoint3, VertexPoint3> {
 public:
  static constexpr const char* kTypeTag = "TEST_POINT_DISTANCE";
  const char* typeTag() const override { return kTypeTag; }
  void computeResidual(Residual& residual) const override {
    residual = vertexAs<1>()->estimate() - vertexAs<0>()->estimate() - measurement_;
  }
};

TEST(BadApiInput, SchurSolverRefusesAnEdgeBetweenMarginalisedVertices) {
  for (const char* solver : {"schur_dense", "schur_cholmod", "dense", "cholmod"}) {
    Graph graph;
    auto* a = graph.addVertex(std::make_unique<VertexPoint3>(10));
    auto* b = graph.addVertex(std::make_unique<VertexPoint3>(11, Eigen::Vector3d(1, 2, 3)));
    a->setFixed(true);
    auto* c = graph.addVertex(std::make_unique<VertexPoint3>(12));
    for (auto [from, to] : {std::pair{a, b}, std::pair{b, c}}) {
      auto edge = std::make_unique<EdgePointDistance>();
      edge->setVertex(0, from);
      edge->setVertex(1, to);
      edge->setMeasurement(Eigen::Vector3d(1, 1, 1));
      graph.addEdge(std::move(edge));
    }
    SolverOptions options;
    options.linearSolver = solver;
    if (std::string(solver).starts_with("schur")) {
      EXPECT_TRUE(optimizeFailsWith(graph, {"11", "12"}, options)) << solver;
    } else {
      const SolverSummary summary = Optimizer(options).optimize(graph);
      EXPECT_LT(summary.finalCost, 1e-16) << solver;
    }
  }
}

}  // namespace
}  // namespace lrsvo::test
