// The BAL reader, writer, graph builder and generator, and the BAL camera
// model (EdgeBalProjection) against the format's definition.
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "lrsvo/edges/edge_bal_projection.h"
#include "lrsvo/frontend/datasets/bal_problem.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/optimizer.h"
#include "lrsvo/vertices/vertex_bal_camera.h"
#include "lrsvo/vertices/vertex_point3.h"

namespace lrsvo {
namespace {

const std::string kDubrovnik = LRSVO_SHARED_DATA "/bal/dubrovnik-3-7-pre.txt";

bool bitwiseEqual(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

template <typename Derived>
bool bitwiseEqual(const Eigen::MatrixBase<Derived>& a, const Eigen::MatrixBase<Derived>& b) {
  for (Eigen::Index i = 0; i < a.size(); ++i)
    if (!bitwiseEqual(a[i], b[i])) return false;
  return true;
}

void expectIdentical(const BalProblem& a, const BalProblem& b) {
  ASSERT_EQ(a.cameras.size(), b.cameras.size());
  ASSERT_EQ(a.points.size(), b.points.size());
  ASSERT_EQ(a.observations.size(), b.observations.size());
  for (std::size_t i = 0; i < a.cameras.size(); ++i) EXPECT_TRUE(bitwiseEqual(a.cameras[i], b.cameras[i])) << i;
  for (std::size_t i = 0; i < a.points.size(); ++i) EXPECT_TRUE(bitwiseEqual(a.points[i], b.points[i])) << i;
  for (std::size_t i = 0; i < a.observations.size(); ++i) {
    EXPECT_EQ(a.observations[i].camera, b.observations[i].camera) << i;
    EXPECT_EQ(a.observations[i].point, b.observations[i].point) << i;
    EXPECT_TRUE(bitwiseEqual(a.observations[i].pixel, b.observations[i].pixel)) << i;
  }
}

// A private directory for the files a test writes, removed afterwards.
class BalFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ =
        std::filesystem::temp_directory_path() / ("lrsvo_test_bal_" + std::to_string(::getpid()) + "_" +
                                                  ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(directory_);
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  std::string path(const std::string& name) const { return (directory_ / name).string(); }

  std::string write(const std::string& name, const std::string& text) const {
    const std::string file = path(name);
    std::ofstream(file) << text;
    return file;
  }

  // readBal must throw a ParseError naming this file and 1-based line.
  void expectParseError(const std::string& text, int line, const std::string& fragment) const {
    const std::string file = write("bad.txt", text);
    try {
      readBal(file);
      ADD_FAILURE() << "no error for:\n" << text;
    } catch (const ParseError& e) {
      EXPECT_EQ(e.file(), file);
      EXPECT_EQ(e.line(), line) << e.what();
      EXPECT_NE(std::string(e.what()).find(file + ":" + std::to_string(line) + ":"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  }

 private:
  std::filesystem::path directory_;
};

TEST(Bal, DubrovnikLoadsWithTheFormatsLayout) {
  const BalProblem problem = readBal(kDubrovnik);
  ASSERT_EQ(problem.cameras.size(), 3u);
  ASSERT_EQ(problem.points.size(), 7u);
  ASSERT_EQ(problem.observations.size(), 19u);
  EXPECT_EQ(problem.observations[0].camera, 0);
  EXPECT_EQ(problem.observations[0].point, 0);
  EXPECT_EQ(problem.observations[0].pixel, Eigen::Vector2d(-3.859900e+02, 3.871200e+02));
  EXPECT_EQ(problem.observations[18].camera, 2);
  EXPECT_EQ(problem.observations[18].point, 6);
  EXPECT_EQ(problem.cameras[0][0], -1.6943983532198115e-02);
  EXPECT_EQ(problem.cameras[0][6], 1.4300319432711681e+03);
  EXPECT_EQ(problem.points[6][2], -5.2070299568846060e+01);
  // The published start reprojects to within a few tens of pixels only when
  // the camera model (looking down -z, p = -P / P_z) is the format's.
  EXPECT_LT(rmsReprojectionError(problem), 20.0);
}

TEST(Bal, DubrovnikSolvesAndConverges) {
  BalProblem problem = readBal(kDubrovnik);
  Graph graph = makeBalGraph(problem);
  SolverOptions options = SolverOptions::fromName("lm_schur_cholmod");
  options.maxIterations = 200;
  const SolverSummary summary = Optimizer(options).optimize(graph);
  EXPECT_TRUE(summary.converged()) << summary.fullReport();
  EXPECT_LT(summary.finalCost, summary.initialCost);
  // 38 residuals and 48 unknowns: an exact fit exists.
  EXPECT_LT(summary.finalCost, 1e-6 * summary.initialCost) << summary.briefReport();
  updateFromGraph(problem, graph);
  EXPECT_NEAR(0.5 * 2.0 * 19 * std::pow(rmsReprojectionError(problem), 2), summary.finalCost,
              1e-9 * summary.initialCost);
}

TEST(Bal, GraphLayoutAndUpdate) {
  BalProblem problem = readBal(kDubrovnik);
  Graph graph = makeBalGraph(problem, "Huber", 2.0);
  ASSERT_EQ(graph.vertices().size(), 10u);
  ASSERT_EQ(graph.edges().size(), 19u);
  for (int i = 0; i < 3; ++i) {
    auto* camera = dynamic_cast<VertexBalCamera*>(graph.vertex(i));
    ASSERT_NE(camera, nullptr);
    EXPECT_FALSE(camera->marginalized());
    EXPECT_EQ(camera->estimate(), problem.cameras[i]);
  }
  for (int j = 0; j < 7; ++j) {
    auto* point = dynamic_cast<VertexPoint3*>(graph.vertex(3 + j));
    ASSERT_NE(point, nullptr);
    EXPECT_TRUE(point->marginalized());
    EXPECT_EQ(point->estimate(), problem.points[j]);
  }
  const auto* edge = dynamic_cast<const EdgeBalProjection*>(graph.edges()[4].get());
  ASSERT_NE(edge, nullptr);
  ASSERT_NE(edge->robustKernel(), nullptr);
  EXPECT_STREQ(edge->robustKernel()->name(), "Huber");
  EXPECT_EQ(edge->vertex(0)->id(), problem.observations[4].camera);
  EXPECT_EQ(edge->vertex(1)->id(), 3 + problem.observations[4].point);
  EXPECT_EQ(edge->measurement(), problem.observations[4].pixel);

  static_cast<VertexPoint3*>(graph.vertex(5))->setEstimateVector(Eigen::Vector3d(1, 2, 3));
  updateFromGraph(problem, graph);
  EXPECT_EQ(problem.points[2], Eigen::Vector3d(1, 2, 3));

  BalProblem wrongSize = problem;
  wrongSize.points.emplace_back(0, 0, 0);
  EXPECT_THROW(updateFromGraph(wrongSize, graph), Error);
}

TEST_F(BalFiles, WriteReadRoundTripIsExact) {
  BalProblem problem = generateBalProblem({.cameras = 5, .points = 60, .seed = 3});
  // Values whose shortest decimal form needs all 17 digits, extremes and a signed zero.
  problem.points[0] = Eigen::Vector3d(0.1, 1.0 / 3.0, -0.0);
  problem.points[1] = Eigen::Vector3d(std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::max(),
                                      -std::numeric_limits<double>::min());
  problem.cameras[0][7] = std::nextafter(1.0, 2.0);
  const std::string file = path("round_trip.txt");
  writeBal(problem, file);
  expectIdentical(problem, readBal(file));

  const BalProblem dubrovnik = readBal(kDubrovnik);
  writeBal(dubrovnik, file);
  expectIdentical(dubrovnik, readBal(file));
}

TEST_F(BalFiles, ReadsCamerasSpreadOverLinesAndPlusSigns) {
  const std::string file = write("layout.txt",
                                 "2 1 2\n0 0 +1.5 -2\n1 0 3 4e1\n"
                                 "0 0 0 0 0 -5 500 0 0   0 0 0\n0 0 -5\n1000 0 0\n"
                                 "1 2 3\n");
  const BalProblem problem = readBal(file);
  EXPECT_EQ(problem.observations[0].pixel, Eigen::Vector2d(1.5, -2));
  EXPECT_EQ(problem.observations[1].pixel, Eigen::Vector2d(3, 40));
  EXPECT_EQ(problem.cameras[0][6], 500.0);
  EXPECT_EQ(problem.cameras[1][6], 1000.0);
  EXPECT_EQ(problem.points[0], Eigen::Vector3d(1, 2, 3));
}

// Header, 2 observations, 2 cameras (9 lines each), 1 point (3 lines): 24 lines.
std::string smallBalText() {
  std::string text = "2 1 2\n0 0 1.5 -2.5\n1 0 3.5 4.5\n";
  for (int camera = 0; camera < 2; ++camera)
    for (const char* value : {"0.01", "0.02", "0.03", "0", "0", "-5", "500", "0", "0"})
      text += std::string(value) + "\n";
  return text + "1\n2\n3\n";
}

std::string replaceLine(const std::string& text, int line, const std::string& replacement) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  for (std::size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1)
    lines.push_back(text.substr(start, end - start));
  lines.at(line - 1) = replacement;
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

TEST_F(BalFiles, TheSmallFileIsValid) { EXPECT_NO_THROW(readBal(write("good.txt", smallBalText()))); }

TEST_F(BalFiles, MalformedNumbersNameTheLine) {
  expectParseError(replaceLine(smallBalText(), 3, "1 0 3.5x 4.5"), 3, "malformed number '3.5x'");
  expectParseError(replaceLine(smallBalText(), 12, "1.2.3"), 12, "camera 0");
  expectParseError(replaceLine(smallBalText(), 2, "0 zero 1.5 -2.5"), 2, "point index of observation 0");
  expectParseError(replaceLine(smallBalText(), 1, "2 one 2"), 1, "malformed integer 'one'");
  expectParseError(replaceLine(smallBalText(), 22, "1e999"), 22, "out of the range");
}

TEST_F(BalFiles, NonFiniteValuesNameTheLine) {
  expectParseError(replaceLine(smallBalText(), 20, "nan"), 20, "non-finite value 'nan' in camera 1");
  expectParseError(replaceLine(smallBalText(), 24, "-inf"), 24, "point 0");
  expectParseError(replaceLine(smallBalText(), 3, "1 0 inf 4.5"), 3, "observation 1");
}

TEST_F(BalFiles, IndicesOutOfRangeNameTheLine) {
  expectParseError(replaceLine(smallBalText(), 3, "2 0 3.5 4.5"), 3, "names camera 2, outside 0..1");
  expectParseError(replaceLine(smallBalText(), 2, "0 -1 1.5 -2.5"), 2, "names point -1");
}

TEST_F(BalFiles, BadCountsNameTheHeader) {
  expectParseError(replaceLine(smallBalText(), 1, "0 1 2"), 1, "camera count must be a positive int");
  expectParseError(replaceLine(smallBalText(), 1, "2 -1 2"), 1, "point count");
  expectParseError(replaceLine(smallBalText(), 1, "2 1 99999999999"), 1, "observation count");
  expectParseError("", 1, "the file ends early");
}

TEST_F(BalFiles, TruncatedFilesNameTheLastLine) {
  // The header promises 2 points: the file ends at line 24 wanting more.
  expectParseError(replaceLine(smallBalText(), 1, "2 2 2"), 24, "the file ends early: point 1 is missing");
  // Cut inside the cameras, with blank lines after the last number.
  const std::string text = smallBalText();
  std::size_t cut = 0;
  for (int line = 0; line < 15; ++line) cut = text.find('\n', cut) + 1;
  expectParseError(text.substr(0, cut) + "\n\n", 15, "camera 1 is missing");
}

TEST_F(BalFiles, TrailingGarbageNamesItsLine) {
  expectParseError(smallBalText() + "\n\n7\n", 27, "trailing content");
  expectParseError(smallBalText() + "end", 25, "trailing content");
}

TEST_F(BalFiles, MissingFileNamesThePath) {
  const std::string missing = path("no_such_file.txt");
  try {
    readBal(missing);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
  EXPECT_THROW(readBal(path("")), Error);  // a directory
  EXPECT_THROW(writeBal(readBal(kDubrovnik), path("no_dir/out.txt")), Error);
}

TEST(Bal, GeneratorIsDeterministicPerSeed) {
  const BalGeneratorOptions options{.cameras = 8, .points = 200, .seed = 7};
  const BalProblem a = generateBalProblem(options);
  expectIdentical(a, generateBalProblem(options));
  BalGeneratorOptions other = options;
  other.seed = 8;
  const BalProblem b = generateBalProblem(other);
  EXPECT_FALSE(bitwiseEqual(a.cameras[0], b.cameras[0]));
  EXPECT_FALSE(bitwiseEqual(a.points[0], b.points[0]));
}

TEST(Bal, GeneratorMakesAValidProblemOfTheAskedShape) {
  const BalGeneratorOptions options{.cameras = 30, .points = 2000, .observationsPerPoint = 5, .seed = 2};
  const BalProblem problem = generateBalProblem(options);
  ASSERT_EQ(problem.cameras.size(), 30u);
  ASSERT_EQ(problem.points.size(), 2000u);
  std::vector<int> views(problem.points.size(), 0), seen(problem.cameras.size(), 0);
  for (const BalObservation& o : problem.observations) {
    ++views[o.point];
    ++seen[o.camera];
    const auto& camera = problem.cameras[o.camera];
    const Eigen::Vector3d P = angleAxisRotate(camera.head<3>(), problem.points[o.point]) + camera.segment<3>(3);
    EXPECT_LT(P.z(), -1.0) << "point " << o.point << " behind camera " << o.camera;
    EXPECT_LT(o.pixel.norm(), camera[6]) << "observation more than 45 degrees off axis";
  }
  for (int v : views) EXPECT_GE(v, 2);
  for (int s : seen) EXPECT_GT(s, 0);
  const double mean = static_cast<double>(problem.observations.size()) / problem.points.size();
  EXPECT_NEAR(mean, 5.0, 0.25);
  for (const auto& camera : problem.cameras) {
    EXPECT_GE(camera[6], 500.0);
    EXPECT_LE(camera[6], 1000.0);
  }
  // The start is perturbed: residuals well above the 1 px noise.
  EXPECT_GT(rmsReprojectionError(problem), 2.0);
}

TEST(Bal, NoiseFreeGeneratedProblemHasZeroCost) {
  const BalProblem problem = generateBalProblem(
      {.cameras = 6, .points = 100, .pixelNoise = 0, .rotationNoise = 0, .translationNoise = 0, .pointNoise = 0});
  EXPECT_LT(makeBalGraph(problem).cost(), 1e-18);
  EXPECT_THROW(generateBalProblem({.cameras = 1}), Error);
  EXPECT_THROW(generateBalProblem({.observationsPerPoint = 1}), Error);
  // More views per point than cameras: every camera sees every point.
  EXPECT_EQ(generateBalProblem({.cameras = 3, .points = 10, .observationsPerPoint = 5}).observations.size(), 30u);
  EXPECT_THROW(generateBalProblem({.pixelNoise = -1.0}), Error);
}

// Analytic against central-difference Jacobians, relative to the block's size.
void expectJacobiansMatch(const Eigen::Matrix<double, 9, 1>& cameraParameters, const Eigen::Vector3d& position) {
  VertexBalCamera camera(0);
  camera.setEstimateVector(cameraParameters);
  VertexPoint3 point(1, position);
  EdgeBalProjection edge;
  edge.setVertex(0, &camera);
  edge.setVertex(1, &point);
  edge.setMeasurement(Eigen::Vector2d(3.0, -4.0));
  edge.computeJacobians();
  const Eigen::Matrix<double, 2, 9> cameraAnalytic = edge.jacobian<0>();
  const Eigen::Matrix<double, 2, 3> pointAnalytic = edge.jacobian<1>();
  edge.computeNumericJacobians();
  const double cameraScale = edge.jacobian<0>().cwiseAbs().maxCoeff();
  const double pointScale = edge.jacobian<1>().cwiseAbs().maxCoeff();
  EXPECT_LE((cameraAnalytic - edge.jacobian<0>()).cwiseAbs().maxCoeff(), 1e-7 * cameraScale)
      << "camera " << cameraParameters.transpose() << "\nanalytic\n"
      << cameraAnalytic << "\nnumeric\n"
      << edge.jacobian<0>();
  EXPECT_LE((pointAnalytic - edge.jacobian<1>()).cwiseAbs().maxCoeff(), 1e-7 * pointScale)
      << "point " << position.transpose() << "\nanalytic\n"
      << pointAnalytic << "\nnumeric\n"
      << edge.jacobian<1>();
}

TEST(Bal, ProjectionJacobiansMatchNumericDifferences) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    // Rotations from large angles down to exactly zero.
    const double angle =
        trial < 16 ? 2.5 * std::abs(unit(random)) : (trial < 19 ? std::pow(10.0, -3 * (trial - 15)) : 0);
    const Eigen::Vector3d axis = Eigen::Vector3d(unit(random), unit(random), unit(random)).normalized();
    const Eigen::Vector3d position(10 * unit(random), 10 * unit(random), 10 * unit(random));
    // Place the point in front of the camera (P_z < 0), within the image.
    const Eigen::Vector3d inCamera(3 * unit(random), 3 * unit(random), -8.0 - 4.0 * std::abs(unit(random)));
    Eigen::Matrix<double, 9, 1> camera;
    camera.head<3>() = angle * axis;
    camera.segment<3>(3) = inCamera - angleAxisRotate(camera.head<3>(), position);
    camera[6] = 750 + 250 * unit(random);
    camera[7] = 0.1 * unit(random);
    camera[8] = 0.02 * unit(random);
    SCOPED_TRACE("trial " + std::to_string(trial) + ", angle " + std::to_string(angle));
    expectJacobiansMatch(camera, position);
  }
}

TEST(Bal, ResidualIsTheProjectionMinusTheMeasurement) {
  const BalProblem problem = readBal(kDubrovnik);
  Graph graph = makeBalGraph(problem);
  for (std::size_t i = 0; i < problem.observations.size(); ++i) {
    const BalObservation& o = problem.observations[i];
    const Eigen::Vector2d r = projectBal(problem.cameras[o.camera], problem.points[o.point]) - o.pixel;
    EXPECT_NEAR(graph.edges()[i]->cost(), 0.5 * r.squaredNorm(), 1e-12 * (1 + r.squaredNorm()));
  }
}

TEST(Bal, EveryLinearSolverReachesTheSameCost) {
  const BalProblem problem = generateBalProblem({.cameras = 10, .points = 300, .seed = 5});
  std::vector<double> finalCosts;
  for (const char* name : {"lm_dense", "lm_cholmod", "lm_schur_dense", "lm_schur_cholmod"}) {
    Graph graph = makeBalGraph(problem);
    SolverOptions options = SolverOptions::fromName(name);
    options.maxIterations = 100;
    options.functionTolerance = 1e-12;
    options.parameterTolerance = 1e-12;
    const SolverSummary summary = Optimizer(options).optimize(graph);
    EXPECT_TRUE(summary.converged()) << summary.fullReport();
    finalCosts.push_back(summary.finalCost);
  }
  for (double cost : finalCosts) EXPECT_NEAR(cost, finalCosts.front(), 1e-6 * finalCosts.front());
  // The noise level: about one pixel per coordinate, less the fitted degrees of freedom.
  EXPECT_LT(finalCosts.front(), 1.1 * problem.observations.size());
}

}  // namespace
}  // namespace lrsvo
