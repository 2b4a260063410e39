#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <Eigen/Core>

namespace lrsvo {

// How an edge without hand-written (or automatic) Jacobians differentiates
// its residual numerically (docs/autodiff.md, "Numeric differences").
enum class NumericDifference {
  kForward,  // (r(x + h) - r(x)) / h: one evaluation per column, error h |r''| / 2 + 2 eps |r| / h
  kCentral,  // (r(x + h) - r(x - h)) / 2h: two per column, error h^2 |r'''| / 6 + eps |r| / h
  kRidders,  // central differences at shrinking h, Richardson-extrapolated to h = 0 (about 2 x 10 per column)
};

struct NumericDiffOptions {
  NumericDifference method = NumericDifference::kCentral;
  // Step as a fraction of the parameter's magnitude, h = relativeStep * max(|x_i|, typicalMagnitude)
  // (|x_i| read as 0 for the tangent coordinates of manifold vertices, which
  // are 0 at the estimate). A negative value takes
  // the method's optimal step for residuals of unit relative curvature:
  // eps^(1/2) forward, eps^(1/3) central, and 1e-3 as Ridders' first step.
  double relativeStep = -1.0;
  // Where the step stops shrinking with the parameter. 1 suits parameters of
  // order one or more and residuals that do not change on a finer scale than
  // their parameters' units (a step far below that drowns in rounding). 0
  // makes the step purely relative, for parameters far below one whose
  // residuals change on their own scale (a regression's 6e-9 rate constant).
  double typicalMagnitude = 1.0;

  double step() const {
    if (relativeStep > 0.0) return relativeStep;
    constexpr double eps = std::numeric_limits<double>::epsilon();
    switch (method) {
      case NumericDifference::kForward: return std::sqrt(eps);
      case NumericDifference::kCentral: return std::cbrt(eps);
      case NumericDifference::kRidders: break;
    }
    return 1e-3;
  }
};

// The derivative of r(t) at t = 0 along one coordinate, where
// evaluate(t, residual) fills r at t (the coordinate moved by t), r0 = r(0)
// and h the step for this coordinate.
template <typename Residual, typename Evaluate>
Residual numericDerivative(const Evaluate& evaluate, const Residual& r0, double h, NumericDifference method) {
  Residual plus, minus;
  if (method == NumericDifference::kForward) {
    evaluate(h, plus);
    return (plus - r0) / h;
  }
  auto central = [&](double step) {
    evaluate(step, plus);
    evaluate(-step, minus);
    return Residual((plus - minus) / (2.0 * step));
  };
  if (method == NumericDifference::kCentral) return central(h);

  // Ridders (Numerical Recipes, 3rd ed., 5.7): a Neville tableau of central
  // differences at steps h, h / c, h / c^2, ...; each column removes the next
  // even power of h. The entry with the smallest change from its neighbours
  // is returned; the search stops once the diagonal's change grows past
  // kSafe times the best error estimate (rounding has taken over).
  constexpr int kSize = 10;
  constexpr double kShrink = 1.4, kShrink2 = kShrink * kShrink, kSafe = 2.0;
  std::array<std::array<Residual, kSize>, kSize> tableau;
  double step = h;
  tableau[0][0] = central(step);
  Residual best = tableau[0][0];
  double bestError = std::numeric_limits<double>::infinity();
  for (int i = 1; i < kSize; ++i) {
    step /= kShrink;
    tableau[0][i] = central(step);
    double factor = kShrink2;
    for (int j = 1; j <= i; ++j) {
      tableau[j][i] = (tableau[j - 1][i] * factor - tableau[j - 1][i - 1]) / (factor - 1.0);
      factor *= kShrink2;
      const double error = std::max((tableau[j][i] - tableau[j - 1][i]).template lpNorm<Eigen::Infinity>(),
                                    (tableau[j][i] - tableau[j - 1][i - 1]).template lpNorm<Eigen::Infinity>());
      if (error <= bestError) {
        bestError = error;
        best = tableau[j][i];
      }
    }
    if ((tableau[i][i] - tableau[i - 1][i - 1]).template lpNorm<Eigen::Infinity>() >= kSafe * bestError) break;
  }
  return best;
}

}  // namespace lrsvo
