// g2o's text format: the shared example files load, cost what g2o's error
// definition gives, round-trip byte-exactly, and bad input is reported by line.

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "lrsvo/edges/edge_se2.h"
#include "lrsvo/edges/edge_se3_quat.h"
#include "lrsvo/edges/g2o_file.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/optimizer.h"
#include "lrsvo/vertices/vertex_point3.h"
#include "unit_tests/graph/test_problems.h"

namespace lrsvo::test {
// Named, so that helpers stay apart from other files' in a unity build.
namespace g2o_file {
namespace {

const std::string kPose2 = LRSVO_SHARED_DATA "/pose_graphs/pose2example.txt";
const std::string kPose3 = LRSVO_SHARED_DATA "/pose_graphs/pose3example.txt";

std::string g2oText(const Graph& graph) {
  std::ostringstream out;
  saveG2o(graph, out);
  return out.str();
}

Graph g2oGraph(const std::string& text) {
  std::istringstream in(text);
  return loadG2o(in, "test.g2o");
}

// The lines of a file split into words.
std::vector<std::vector<std::string>> wordsOf(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<std::string>> lines;
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::vector<std::string> fields;
    for (std::string word; words >> word;) fields.push_back(word);
    if (!fields.empty()) lines.push_back(fields);
  }
  return lines;
}

double at(const std::vector<std::string>& fields, std::size_t k) { return std::stod(fields.at(k)); }

// Upper bound of the difference of two evaluations of 1/2 r^T Omega r whose
// residual components differ by at most `delta` each: |Omega| (2 |r| + d delta) d delta / 2.
double costRoundingBound(const Eigen::MatrixXd& information, const Eigen::VectorXd& residual, double delta) {
  const double d = static_cast<double>(residual.size());
  return 0.5 * information.norm() * (2.0 * residual.norm() + d * delta) * std::sqrt(d) * delta;
}

// Each residual is a few tens of operations on coordinates of magnitude at most `scale`.
double residualRounding(double scale) { return 50.0 * std::numeric_limits<double>::epsilon() * (1.0 + scale); }

// g2o's error for EDGE_SE2, evaluated straight from the file's words with
// Eigen's transforms: e = t2v(Z^-1 (X_i^-1 X_j)), the angle in (-pi, pi].
TEST(G2oFile, Pose2ExampleCostIsG2osErrorDefinition) {
  std::map<int, Eigen::Isometry2d> poses;
  const auto isometry = [](double x, double y, double theta) {
    Eigen::Isometry2d pose = Eigen::Isometry2d::Identity();
    pose.linear() = Eigen::Rotation2Dd(theta).toRotationMatrix();
    pose.translation() = Eigen::Vector2d(x, y);
    return pose;
  };
  double expected = 0.0, bound = 0.0, scale = 0.0;
  int edges = 0;
  for (const auto& f : wordsOf(kPose2)) {
    if (f[0] == "VERTEX_SE2") {
      poses[std::stoi(f[1])] = isometry(at(f, 2), at(f, 3), at(f, 4));
      scale = std::max({scale, std::abs(at(f, 2)), std::abs(at(f, 3))});
    }
    if (f[0] != "EDGE_SE2") continue;
    const Eigen::Isometry2d Z = isometry(at(f, 3), at(f, 4), at(f, 5));
    const Eigen::Isometry2d E = Z.inverse() * (poses.at(std::stoi(f[1])).inverse() * poses.at(std::stoi(f[2])));
    const Eigen::Vector3d e(E.translation().x(), E.translation().y(), Eigen::Rotation2Dd(E.linear()).smallestAngle());
    Eigen::Matrix3d omega;
    omega << at(f, 6), at(f, 7), at(f, 8), at(f, 7), at(f, 9), at(f, 10), at(f, 8), at(f, 10), at(f, 11);
    expected += 0.5 * e.dot(omega * e);
    bound += costRoundingBound(omega, e, residualRounding(scale));
    ++edges;
  }
  const Graph graph = loadG2oFile(kPose2);
  EXPECT_EQ(graph.vertices().size(), poses.size());
  EXPECT_EQ(static_cast<int>(graph.edges().size()), edges);
  EXPECT_GT(expected, 0.0);
  EXPECT_NEAR(graph.cost(), expected, bound);
}

// g2o's error for EDGE_SE3:QUAT: translation and quaternion vector part (w >= 0) of Z^-1 (X_i^-1 X_j).
TEST(G2oFile, Pose3ExampleCostIsG2osErrorDefinition) {
  std::map<int, Eigen::Isometry3d> poses;
  const auto isometry = [](const std::vector<std::string>& f, std::size_t first) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = Eigen::Quaterniond(at(f, first + 6), at(f, first + 3), at(f, first + 4), at(f, first + 5))
                        .normalized()
                        .matrix();
    pose.translation() = Eigen::Vector3d(at(f, first), at(f, first + 1), at(f, first + 2));
    return pose;
  };
  double expected = 0.0, bound = 0.0;
  int edges = 0;
  for (const auto& f : wordsOf(kPose3)) {
    if (f[0] == "VERTEX_SE3:QUAT") poses[std::stoi(f[1])] = isometry(f, 2);
    if (f[0] != "EDGE_SE3:QUAT") continue;
    const Eigen::Isometry3d E =
        isometry(f, 3).inverse() * (poses.at(std::stoi(f[1])).inverse() * poses.at(std::stoi(f[2])));
    Eigen::Quaterniond q(E.linear());
    if (q.w() < 0.0) q.coeffs() = -q.coeffs();
    Eigen::Matrix<double, 6, 1> e;
    e << E.translation(), q.vec();
    Eigen::Matrix<double, 6, 6> omega;
    std::size_t k = 10;
    for (int r = 0; r < 6; ++r)
      for (int c = r; c < 6; ++c) omega(r, c) = omega(c, r) = at(f, k++);
    expected += 0.5 * e.dot(omega * e);
    bound += costRoundingBound(omega, e, residualRounding(3.0));
    ++edges;
  }
  const Graph graph = loadG2oFile(kPose3);
  EXPECT_EQ(graph.vertices().size(), poses.size());
  EXPECT_EQ(static_cast<int>(graph.edges().size()), edges);
  EXPECT_GT(expected, 0.0);
  EXPECT_NEAR(graph.cost(), expected, bound);
}

void expectExactRoundTrip(const std::string& path) {
  const Graph original = loadG2oFile(path);
  const std::string first = g2oText(original);
  const Graph loaded = g2oGraph(first);
  EXPECT_EQ(g2oText(loaded), first);
  EXPECT_EQ(loaded.estimates(), original.estimates());
  EXPECT_EQ(loaded.cost(), original.cost());
}

TEST(G2oFile, Pose2ExampleRoundTripsExactly) { expectExactRoundTrip(kPose2); }
TEST(G2oFile, Pose3ExampleRoundTripsExactly) { expectExactRoundTrip(kPose3); }

TEST(G2oFile, ValuesWithAllDigitsRoundTripExactly) {
  const std::string text =
      "VERTEX_SE2 4 0.10000000000000001 -0.33333333333333331 3.1415926535897931\n"
      "FIX 4\n"
      "VERTEX_SE2 7 1e-300 12345.678901234567 -2.5\n"
      "EDGE_SE2 4 7 0.30000000000000004 -0 0.10000000000000001 2 0.5 0 3 0 4\n";
  const Graph graph = g2oGraph(text);
  EXPECT_TRUE(graph.vertex(4)->fixed());
  EXPECT_FALSE(graph.vertex(7)->fixed());
  EXPECT_EQ(static_cast<const VertexSE2*>(graph.vertex(7))->pose()[0], 1e-300);
  EXPECT_EQ(g2oText(graph), text);
}

TEST(G2oFile, CommentsBlankLinesAPlusSignAndAFinalLineWithoutNewlineAreRead) {
  const Graph graph = g2oGraph(
      "# a comment\n\n   \nVERTEX_SE2 0 0 0 0\n  # indented comment\nVERTEX_SE2 1 +1 0 0\n"
      "EDGE_SE2 0 1 1 0 0 1 0 0 1 0 1");
  EXPECT_EQ(graph.vertices().size(), 2u);
  EXPECT_EQ(graph.edges().size(), 1u);
  EXPECT_EQ(graph.cost(), 0.0);
}

// The ParseError of loading `text`, which must fail on `line` with a message containing `fragment`.
void expectParseError(const std::string& text, int line, const std::string& fragment) {
  try {
    g2oGraph(text);
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const ParseError& error) {
    EXPECT_EQ(error.file(), "test.g2o");
    EXPECT_EQ(error.line(), line) << error.what();
    EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos) << error.what();
  }
}

const std::string kTwoPoses = "VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0 0\n";
const std::string kIdentitySE3 = " 0 0 0 0 0 0 1\n";
const std::string kSE3Information = " 1 0 0 0 0 0 1 0 0 0 0 1 0 0 0 1 0 0 1 0 1";

TEST(G2oFile, UnknownTagIsAnError) { expectParseError(kTwoPoses + "VERTEX_XY 2 0 0\n", 3, "unknown tag 'VERTEX_XY'"); }

TEST(G2oFile, TruncatedLinesAreErrors) {
  expectParseError("VERTEX_SE2 0 0 0\n", 1, "truncated line, 4 values expected after the tag, found 3");
  expectParseError(kTwoPoses + "EDGE_SE2 0 1 1 0 0 1 0 0 1 0\n", 3, "truncated line");
  expectParseError("VERTEX_SE3:QUAT 0 0 0 0 0 0 0\n", 1, "truncated line");
  expectParseError("VERTEX_SE2 0 0 0 0\nFIX\n", 2, "FIX: truncated line");
}

TEST(G2oFile, TrailingDataIsAnError) { expectParseError("VERTEX_SE2 0 0 0 0 5\n", 1, "unexpected trailing data '5'"); }

TEST(G2oFile, MalformedAndNonFiniteNumbersAreErrors) {
  expectParseError("VERTEX_SE2 0 0 nan 0\n", 1, "'nan' is not finite");
  expectParseError("VERTEX_SE2 0 0 0 inf\n", 1, "'inf' is not finite");
  expectParseError("VERTEX_SE2 0 0 -inf 0\n", 1, "not finite");
  expectParseError("VERTEX_SE2 0 1e999 0 0\n", 1, "'1e999' is out of the range of a double");
  expectParseError("VERTEX_SE2 0 +-1 0 0\n", 1, "'+-1' is not a number");
  expectParseError("VERTEX_SE2 0 x 0 0\n", 1, "'x' is not a number");
  expectParseError("VERTEX_SE2 1.5 0 0 0\n", 1, "'1.5' is not a vertex id");
  expectParseError(kTwoPoses + "EDGE_SE2 0 1 1 0 0 1 0 0 1 0 NaN\n", 3, "not finite");
}

TEST(G2oFile, EdgeToAMissingVertexIsAnError) {
  expectParseError(kTwoPoses + "EDGE_SE2 0 2 1 0 0 1 0 0 1 0 1\n", 3, "names vertex 2, which is not in the graph");
  expectParseError(kTwoPoses + "FIX 9\n", 3, "FIX: names vertex 9");
}

TEST(G2oFile, EdgeToAVertexOfAnotherTypeIsAnError) {
  expectParseError("VERTEX_SE2 0 0 0 0\nVERTEX_SE3:QUAT 1" + kIdentitySE3 + "EDGE_SE3:QUAT 0 1 0 0 0 0 0 0 1" +
                       kSE3Information + "\n",
                   3, "vertex 0 is a POSE_SE2, not a POSE_SE3_QUAT");
}

TEST(G2oFile, DuplicateVertexIdIsAnError) {
  expectParseError(kTwoPoses + "VERTEX_SE3:QUAT 1" + kIdentitySE3, 3, "duplicate vertex id 1");
}

// The format holds only the upper triangle, so the matrix read is symmetric by
// construction; positive definiteness is what can fail.
TEST(G2oFile, InformationThatIsNotPositiveDefiniteIsAnError) {
  expectParseError(kTwoPoses + "EDGE_SE2 0 1 1 0 0 1 0 0 1 0 0\n", 3, "not positive definite");
  expectParseError(kTwoPoses + "EDGE_SE2 0 1 1 0 0 1 2 0 1 0 1\n", 3, "not positive definite");
  expectParseError(kTwoPoses + "EDGE_SE2 0 1 1 0 0 -1 0 0 1 0 1\n", 3, "not positive definite");
  expectParseError("VERTEX_SE3:QUAT 0" + kIdentitySE3 + "VERTEX_SE3:QUAT 1" + kIdentitySE3 +
                       "EDGE_SE3:QUAT 0 1 0 0 0 0 0 0 1 1 0 0 0 0 0 1 0 0 0 0 1 0 0 0 1 0 0 1 0 -1\n",
                   3, "not positive definite");
}

TEST(G2oFile, QuaternionOffUnitNormIsAnError) {
  expectParseError("VERTEX_SE3:QUAT 0 0 0 0 0 0 0 1.001\n", 1, "quaternion norm");
  expectParseError("VERTEX_SE3:QUAT 0 0 0 0 0 0 0 0\n", 1, "quaternion norm");
  expectParseError("VERTEX_SE3:QUAT 0" + kIdentitySE3 + "VERTEX_SE3:QUAT 1" + kIdentitySE3 +
                       "EDGE_SE3:QUAT 0 1 0 0 0 0.5 0 0 0.5" + kSE3Information + "\n",
                   3, "quaternion norm");
}

TEST(G2oFile, SavingATypeWithoutAG2oFormIsAnErrorAndWritesNothing) {
  Graph graph = g2oGraph(kTwoPoses + "EDGE_SE2 0 1 1 0 0 1 0 0 1 0 1\n");
  static_cast<EdgeSE2*>(graph.edges()[0].get())->setRobustKernel(makeRobustKernel("Huber", 1.0));
  std::ostringstream out;
  EXPECT_THROW(saveG2o(graph, out), Error);
  EXPECT_EQ(out.str(), "");
  graph.addVertex(std::make_unique<VertexPoint3>(5));
  EXPECT_THROW(saveG2o(graph, out), Error);
  EXPECT_EQ(out.str(), "");
}

TEST(G2oFile, MissingFileIsAnError) { EXPECT_THROW(loadG2oFile("/no/such/file.g2o"), Error); }

// Both example files optimise (first vertex fixed for the gauge) to a lower cost.
TEST(G2oFile, ExamplesOptimiseToALowerCost) {
  for (const std::string& path : {kPose2, kPose3}) {
    Graph graph = loadG2oFile(path);
    graph.vertices().front()->setFixed(true);
    const double start = graph.cost();
    const SolverSummary summary = Optimizer(SolverOptions::fromName("lm_cholmod")).optimize(graph);
    EXPECT_LT(summary.finalCost, start) << path;
    EXPECT_EQ(summary.initialCost, start) << path;
  }
}

}  // namespace
}  // namespace g2o_file
}  // namespace lrsvo::test
