#pragma once

#include <memory>
#include <string>

namespace lrsvo {

template <typename Product>
class Registry;

// A robust loss rho(s) on the squared whitened residual norm s, Ceres'
// convention: an edge costs 1/2 rho(s). rho(s) = s without a kernel.
class RobustKernel {
 public:
  // The graph library's kernels (Registry<RobustKernel> adds them on first use).
  static void addBuiltins(Registry<RobustKernel>& registry);

  virtual ~RobustKernel() = default;
  virtual const char* name() const = 0;
  // Returns rho(s) and writes rho'(s) (the IRLS weight) to `weight`.
  virtual double evaluate(double s, double* weight) const = 0;
  double delta() const { return delta_; }
  // The inlier threshold on the residual norm; must be positive and finite.
  void setDelta(double delta);

 protected:
  double delta_ = 1.0;
};

// Creates a registered kernel ("Huber", "Cauchy", "Tukey") with the given delta.
std::shared_ptr<RobustKernel> makeRobustKernel(const std::string& name, double delta);

}  // namespace lrsvo
