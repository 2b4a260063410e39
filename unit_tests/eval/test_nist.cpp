// The NIST StRD nonlinear regression suite (../shared/data/nist): its reader,
// and every problem solved from both starts.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "lrsvo/eval/nist_models.h"
#include "lrsvo/eval/nist_regression.h"
#include "lrsvo/frontend/datasets/nist_problem.h"
#include "lrsvo/graph/error.h"

namespace lrsvo::test {
namespace {

const std::string kFolder = LRSVO_SHARED_DATA "/nist";

TEST(NistProblem, ReadsTheSectionsOfAFile) {
  const NistProblem problem = readNistProblem(kFolder + "/MGH10.dat");
  EXPECT_EQ(problem.name, "MGH10");
  ASSERT_EQ(problem.parameterCount(), 3);
  EXPECT_EQ(problem.starts[0][1], 400000.0);
  EXPECT_EQ(problem.starts[1][2], 250.0);
  EXPECT_EQ(problem.certified[0], 5.6096364710E-03);
  EXPECT_EQ(problem.certifiedResidualSumOfSquares, 8.7945855171E+01);
  ASSERT_EQ(problem.observationCount(), 16);
  EXPECT_EQ(problem.response[0], 3.478000E+04);
  EXPECT_EQ(problem.predictors(15, 0), 1.250000E+02);
}

TEST(NistProblem, ReadsTwoPredictors) {
  const NistProblem problem = readNistProblem(kFolder + "/Nelson.dat");
  EXPECT_EQ(problem.predictors.cols(), 2);
  EXPECT_EQ(problem.observationCount(), 128);
}

// Every problem's model, evaluated at the certified values, gives the
// certified residual sum of squares: the models are the NIST ones. The sums
// are certified to 11 digits; a relative 1e-9 leaves room for the rounding of
// a few hundred squared terms. The parameters are certified to 11 significant
// digits too, which moves each prediction by up to about 1e-10 of the
// responses' size: n (1e-10 max |y|)^2 more, which only a near-exact fit
// (Lanczos1, a sum of 1.4e-25) ever reaches.
TEST(NistProblem, ModelsReproduceTheCertifiedResidualSumsOfSquares) {
  for (const std::string& file : nistProblemFiles(kFolder)) {
    const NistProblem problem = readNistProblem(file);
    const NistModel model = nistModelOf(problem.name);
    double sum = 0.0;
    const double roundingOfParameters = 1e-10 * problem.response.cwiseAbs().maxCoeff();
    for (int i = 0; i < problem.observationCount(); ++i) {
      const Eigen::Vector2d x(problem.predictors(i, 0), problem.predictors.cols() > 1 ? problem.predictors(i, 1) : 0.0);
      const double r =
          nistResponse(model, problem.response[i]) - nistPrediction(model, problem.certified.data(), x.data());
      sum += r * r;
    }
    EXPECT_NEAR(sum, problem.certifiedResidualSumOfSquares,
                1e-9 * problem.certifiedResidualSumOfSquares +
                    problem.observationCount() * roundingOfParameters * roundingOfParameters)
        << problem.name;
  }
}

std::string mgh10Text() {
  return "Dataset Name:  MGH10\n"
         "        Start 1     Start 2           Parameter     Standard Deviation\n"
         "  b1 =        2         0.02       5.6096364710E-03  1.5687892471E-04\n"
         "  b2 =   400000      4000          6.1813463463E+03  2.3309021107E+01\n"
         "  b3 =    25000       250          3.4522363462E+02  7.8486103508E-01\n"
         "Residual Sum of Squares:                    8.7945855171E+01\n"
         "Number of Observations:                            2\n"
         "Data:  y               x\n"
         "      3.478000E+04    5.000000E+01\n"
         "      2.861000E+04    5.500000E+01\n";
}

void expectParseError(const std::string& text, int line, const std::string& fragment) {
  try {
    parseNistProblem(text, "bad.dat");
    ADD_FAILURE() << "no error for text with '" << fragment << "'";
  } catch (const ParseError& error) {
    EXPECT_EQ(error.line(), line) << error.what();
    EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos) << error.what();
  }
}

TEST(NistProblem, BadInputNamesTheLine) {
  const std::string good = mgh10Text();
  EXPECT_NO_THROW(parseNistProblem(good, "good.dat"));
  expectParseError(good.substr(0, good.rfind("      2.861")), 9, "ends after 1 of 2");  // the file's last line
  std::string nan = good;
  nan.replace(nan.find("400000"), 6, "nan");
  expectParseError(nan, 4, "not a finite number");
  std::string shortRow = good;
  shortRow.replace(shortRow.find("    5.500000E+01"), 16, "");
  expectParseError(shortRow, 10, "needs 2 numbers");
  std::string huge = good;
  huge.replace(huge.find("2\nData:"), 1, "1e300");
  expectParseError(huge, 7, "not a count");
  std::string noStarts = good;
  noStarts.replace(noStarts.find("Start 1"), 7, "Begin 1");
  expectParseError(noStarts, 10, "no starting values");
}

TEST(NistProblem, AnUnknownProblemHasNoModel) { EXPECT_THROW(nistModelOf("Unknown7"), Error); }

// The suite's own criterion: every parameter to at least 4 correct digits,
// from both starts, with automatic differentiation and the default LM. One
// solve is not reached and is held to what it reaches, so that a change that
// loses or gains it shows here: BoxBOD from start 1 (Ceres does not solve it
// either), stalled on a plateau; geodesic acceleration solves it (below).
TEST(NistRegression, EveryProblemButOneIsSolvedFromBothStarts) {
  const NistSolveOptions options;
  int unsolved = 0;
  for (const std::string& file : nistProblemFiles(kFolder)) {
    const NistProblem problem = readNistProblem(file);
    for (int start : {1, 2}) {
      const NistSolve solve = solveNist(problem, start, options);
      const bool open = start == 1 && problem.name == "BoxBOD";
      if (open) {
        unsolved += !solve.solved();
        continue;
      }
      EXPECT_TRUE(solve.solved()) << problem.name << " start " << start << ": " << solve.minDigits() << " digits, "
                                  << solve.summary.briefReport();
    }
  }
  EXPECT_EQ(unsolved, 1) << "the open NIST solve is now solved: move it to the solved ones";
}

// MGH10 from start 1 (b2 = 4e5) loses b2's curvature on the way (b1 passes
// near 0): with the damping floor in the parameters' own units b2 is then
// barely damped, jumps to ~4e7 and the solve stalls; with the floor in the
// Jacobi-scaled units (the regression's setting) it converges.
TEST(NistRegression, Mgh10FromStartOneNeedsTheJacobiScaledDampingFloor) {
  const NistProblem problem = readNistProblem(kFolder + "/MGH10.dat");
  NistSolveOptions options;
  ASSERT_TRUE(options.solver.lm.jacobiScaledDiagonal);
  const NistSolve scaled = solveNist(problem, 1, options);
  EXPECT_TRUE(scaled.solved()) << scaled.minDigits() << " digits, " << scaled.summary.briefReport();
  options.solver.lm.jacobiScaledDiagonal = false;
  const NistSolve unscaled = solveNist(problem, 1, options);
  EXPECT_FALSE(unscaled.solved()) << unscaled.summary.briefReport();
}

// BoxBOD from start 1 (b = (1, 1)): plain steps run b2 off to where the model
// is flat in it, b1 at the mean of y; geodesic acceleration's ratio test turns
// those steps down and the solve reaches the certified values.
TEST(NistRegression, BoxBodFromStartOneIsSolvedWithGeodesicAcceleration) {
  const NistProblem problem = readNistProblem(kFolder + "/BoxBOD.dat");
  NistSolveOptions options;
  ASSERT_FALSE(options.solver.lm.geodesicAcceleration);
  const NistSolve plain = solveNist(problem, 1, options);
  EXPECT_FALSE(plain.solved()) << plain.summary.briefReport();
  options.solver.lm.geodesicAcceleration = true;
  const NistSolve accelerated = solveNist(problem, 1, options);
  EXPECT_TRUE(accelerated.solved()) << accelerated.minDigits() << " digits, " << accelerated.summary.briefReport();
}

TEST(NistRegression, CorrectDigitsAreTheLogRelativeError) {
  EXPECT_NEAR(correctDigits(1.0001, 1.0), 4.0, 1e-9);
  EXPECT_NEAR(correctDigits(-2.002, -2.0), 3.0, 1e-9);
  EXPECT_EQ(correctDigits(5.0, 5.0), 11.0);
  EXPECT_EQ(correctDigits(1e9, 1.0), 0.0);
  EXPECT_EQ(correctDigits(std::nan(""), 1.0), 0.0);
}

}  // namespace
}  // namespace lrsvo::test
