#pragma once

#include <limits>
#include <string>

namespace lrsvo {

// How LM damps the normal equations.
enum class Damping {
  kMultiplicative,  // diag(H) * (1 + lambda), the paper's (and Ceres' default) form
  kAdditive,        // diag(H) + lambda
};

// "multiplicative" or "additive"; throws lrsvo::Error on any other name.
Damping dampingFromName(const std::string& name);

// Levenberg-Marquardt's own settings. A step is taken when its gain (actual
// over predicted decrease) exceeds minRelativeDecrease; lambda then shrinks by
// Nielsen's rule, otherwise it grows geometrically (2, 4, 8, ... times).
struct LevenbergMarquardtOptions {
  Damping damping = Damping::kMultiplicative;
  // Starting lambda; a negative value picks the default (1e-4 multiplicative,
  // 1e-4 * max diag(H) additive).
  double initialLambda = -1.0;
  double minRelativeDecrease = 1e-3;
  double minLambda = 1e-16;
  double maxLambda = 1e32;  // beyond it the solve stops (Termination::kDampingLimit)
  // The multiplicative damping lambda * diag(H) clamps diag(H) to this range,
  // so a parameter with no curvature is still damped (Ceres' values).
  double minDiagonal = 1e-6;
  double maxDiagonal = 1e32;
  // Applies that range to diag(H) in the units of the first linearisation's
  // Jacobi scaling (each Jacobian column divided by 1 + its norm there), as
  // Ceres' jacobi_scaling does: parameter i's floor is then
  // minDiagonal (1 + |J_i|)^2, which follows the parameter's own units, where
  // the plain floor is absolute. Off by default; the NIST regression turns it on.
  bool jacobiScaledDiagonal = false;
  // Geodesic acceleration (Transtrum and Sethna): each step v is corrected by
  // a/2, where a solves the damped system for the residuals' second derivative
  // along v (finite differences with step geodesicStep); a step with
  // 2 |a| > maxAccelerationRatio |v| (norms in the damping's metric) is
  // rejected. Steps then follow the curved valleys plain steps leave, which
  // keeps a parameter from running off onto a plateau (NIST's BoxBOD), but
  // leads elsewhere too (docs/autodiff.md); it costs one more residual
  // evaluation and solve per step. Steps a constraint method shaped are taken
  // unaccelerated. Off by default.
  bool geodesicAcceleration = false;
  double geodesicStep = 0.1;
  double maxAccelerationRatio = 0.75;
};

struct SolverOptions {
  std::string algorithm = "lm";                // Registry<OptimizationAlgorithm> name
  std::string linearSolver = "schur_cholmod";  // Registry<LinearSolver> name
  LevenbergMarquardtOptions lm;                // used by "lm"
  int maxIterations = 50;
  double functionTolerance = 1e-6;   // stop when |dF| / F <= this after a step
  double gradientTolerance = 1e-10;  // stop when max |projected gradient| <= this
  double parameterTolerance = 1e-8;  // stop when |dx| <= this * (|x| + this)
  double maxSeconds = std::numeric_limits<double>::infinity();
  int threads = 1;
  bool verbose = false;  // one line per iteration on stderr

  // "<algorithm>_<linear solver>", e.g. "lm_schur_cholmod", "gn_dense".
  // Throws lrsvo::Error when either part is not registered.
  static SolverOptions fromName(const std::string& name);
  std::string name() const { return algorithm + "_" + linearSolver; }
  // Takes the algorithm and linear solver of a name (fromName), keeping every other setting.
  void setName(const std::string& name);
  // Throws lrsvo::Error on an unregistered algorithm or linear solver, fewer
  // than one thread or a negative iteration cap.
  void validate() const;
};

}  // namespace lrsvo
