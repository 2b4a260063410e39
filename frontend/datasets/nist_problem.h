#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace lrsvo {

// A nonlinear regression problem of the NIST Statistical Reference Datasets
// (StRD, www.itl.nist.gov/div898/strd/nls): a model y = f(b; x) + e with its
// parameters' two starting points, the certified least-squares estimates
// (11 significant digits) and their residual sum of squares, and the data.
struct NistProblem {
  std::string name;                       // "MGH10", as the file's "Dataset Name"
  std::array<Eigen::VectorXd, 2> starts;  // "Start 1", "Start 2"
  Eigen::VectorXd certified;              // certified parameter values
  double certifiedResidualSumOfSquares = 0.0;
  Eigen::VectorXd response;    // y, one per observation
  Eigen::MatrixXd predictors;  // one row per observation: x (or x1, x2)

  int parameterCount() const { return static_cast<int>(certified.size()); }
  int observationCount() const { return static_cast<int>(response.size()); }
};

// Reads a NIST StRD ".dat" file. Throws lrsvo::ParseError (file, line) when a
// section is missing or malformed, a number is not finite, the parameter
// lines disagree in count, or the data rows do not match the stated number
// of observations.
NistProblem readNistProblem(const std::string& path);

// The same from text already read; `sourceName` names it in errors.
NistProblem parseNistProblem(const std::string& text, const std::string& sourceName);

}  // namespace lrsvo
