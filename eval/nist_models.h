#pragma once

#include <cmath>
#include <numbers>
#include <string>

namespace lrsvo {

// The models of the NIST StRD nonlinear regression problems, y = f(b; x),
// written once for any scalar type (lrsvo's dual numbers, Ceres' Jets).
// Nelson's model is of log y (nistResponse). A model shared by several
// problems is named after the first of them.
enum class NistModel {
  kBennett5,
  kChwirut,  // Chwirut1, Chwirut2
  kDanWood,
  kEnso,
  kEckerle4,
  kGauss,  // Gauss1, Gauss2, Gauss3
  kHahn1,  // also Thurber: the same cubic over cubic
  kKirby2,
  kLanczos,  // Lanczos1, Lanczos2, Lanczos3
  kMgh09,
  kMgh10,
  kMgh17,
  kMisra1a,  // also BoxBOD: b1 (1 - exp(-b2 x))
  kMisra1b,
  kMisra1c,
  kMisra1d,
  kNelson,
  kRat42,
  kRat43,
  kRoszman1,
};

// The model of a problem by its dataset name ("MGH10"); throws lrsvo::Error
// naming the known problems otherwise.
NistModel nistModelOf(const std::string& datasetName);

// What the model predicts: y itself, or log y for Nelson.
double nistResponse(NistModel model, double y);

// f(b; x) with x the observation's predictors (x, or x1 and x2 for Nelson).
template <typename T>
T nistPrediction(NistModel model, const T* b, const double* x) {
  using std::atan2;
  using std::cos;
  using std::exp;
  using std::log;
  using std::sin;
  using std::sqrt;
  const double pi = std::numbers::pi;
  const double t = x[0];
  switch (model) {
    case NistModel::kBennett5:  // b1 (b2 + x)^(-1 / b3)
      return b[0] * exp(-log(b[1] + t) / b[2]);
    case NistModel::kMisra1a: return b[0] * (1.0 - exp(-b[1] * t));
    case NistModel::kChwirut: return exp(-b[0] * t) / (b[1] + b[2] * t);
    case NistModel::kDanWood:  // b1 x^b2, x > 0
      return b[0] * exp(b[1] * std::log(t));
    case NistModel::kEnso: {
      const double annual = 2.0 * pi * t / 12.0;
      return b[0] + b[1] * cos(annual) + b[2] * sin(annual) + b[4] * cos(2.0 * pi * t / b[3]) +
             b[5] * sin(2.0 * pi * t / b[3]) + b[7] * cos(2.0 * pi * t / b[6]) + b[8] * sin(2.0 * pi * t / b[6]);
    }
    case NistModel::kEckerle4: {
      const T z = (t - b[2]) / b[1];
      return b[0] / b[1] * exp(-0.5 * z * z);
    }
    case NistModel::kGauss: {
      const T u = t - b[3], v = t - b[6];
      return b[0] * exp(-b[1] * t) + b[2] * exp(-u * u / (b[4] * b[4])) + b[5] * exp(-v * v / (b[7] * b[7]));
    }
    case NistModel::kHahn1:
      return (b[0] + t * (b[1] + t * (b[2] + t * b[3]))) / (1.0 + t * (b[4] + t * (b[5] + t * b[6])));
    case NistModel::kKirby2: return (b[0] + t * (b[1] + t * b[2])) / (1.0 + t * (b[3] + t * b[4]));
    case NistModel::kLanczos: return b[0] * exp(-b[1] * t) + b[2] * exp(-b[3] * t) + b[4] * exp(-b[5] * t);
    case NistModel::kMgh09: return b[0] * (t * t + t * b[1]) / (t * t + t * b[2] + b[3]);
    case NistModel::kMgh10: return b[0] * exp(b[1] / (t + b[2]));
    case NistModel::kMgh17: return b[0] + b[1] * exp(-t * b[3]) + b[2] * exp(-t * b[4]);
    case NistModel::kMisra1b: {  // b1 (1 - (1 + b2 x / 2)^-2)
      const T base = 1.0 + b[1] * t / 2.0;
      return b[0] * (1.0 - 1.0 / (base * base));
    }
    case NistModel::kMisra1c:  // b1 (1 - (1 + 2 b2 x)^-1/2)
      return b[0] * (1.0 - 1.0 / sqrt(1.0 + 2.0 * b[1] * t));
    case NistModel::kMisra1d: return b[0] * b[1] * t / (1.0 + b[1] * t);
    case NistModel::kNelson:  // of log y
      return b[0] - b[1] * t * exp(-b[2] * x[1]);
    case NistModel::kRat42: return b[0] / (1.0 + exp(b[1] - b[2] * t));
    case NistModel::kRat43:  // b1 / (1 + exp(b2 - b3 x))^(1 / b4)
      return b[0] * exp(-log(1.0 + exp(b[1] - b[2] * t)) / b[3]);
    case NistModel::kRoszman1:
      // NIST's arctan takes the quadrant of b3 over x - b4 (its certified b1 holds only so).
      return b[0] - b[1] * t - atan2(b[2], t - b[3]) / pi;
  }
  return b[0];
}

}  // namespace lrsvo
