#include "lrsvo/graph/robust_kernel.h"

#include <cmath>

#include "lrsvo/graph/error.h"
#include "lrsvo/graph/registry.h"

namespace lrsvo {

void RobustKernel::setDelta(double delta) {
  if (!(delta > 0.0) || !std::isfinite(delta))
    throw Error(std::string("robust kernel ") + name() + ": delta must be positive and finite");
  delta_ = delta;
}

std::shared_ptr<RobustKernel> makeRobustKernel(const std::string& name, double delta) {
  std::shared_ptr<RobustKernel> kernel = Registry<RobustKernel>::instance().create(name);
  kernel->setDelta(delta);
  return kernel;
}

namespace {

// rho(s) = s inside delta, linear growth of the norm outside.
class HuberKernel : public RobustKernel {
 public:
  const char* name() const override { return "Huber"; }
  double evaluate(double s, double* weight) const override {
    const double b = delta_ * delta_;
    if (s <= b) {
      *weight = 1.0;
      return s;
    }
    const double r = std::sqrt(s);
    *weight = delta_ / r;
    return 2.0 * delta_ * r - b;
  }
};

// rho(s) = b log(1 + s / b), b = delta^2.
class CauchyKernel : public RobustKernel {
 public:
  const char* name() const override { return "Cauchy"; }
  double evaluate(double s, double* weight) const override {
    const double b = delta_ * delta_;
    *weight = 1.0 / (1.0 + s / b);
    return b * std::log1p(s / b);
  }
};

// Tukey's biweight: bounded influence, zero weight beyond delta.
class TukeyKernel : public RobustKernel {
 public:
  const char* name() const override { return "Tukey"; }
  double evaluate(double s, double* weight) const override {
    const double b = delta_ * delta_;
    if (s > b) {
      *weight = 0.0;
      return b / 3.0;
    }
    const double u = 1.0 - s / b;
    *weight = u * u;
    return b / 3.0 * (1.0 - u * u * u);
  }
};

}  // namespace

void RobustKernel::addBuiltins(Registry<RobustKernel>& registry) {
  registry.addType<HuberKernel>("Huber", "quadratic inside delta, linear outside");
  registry.addType<CauchyKernel>("Cauchy", "logarithmic growth, delta^2 log(1 + s / delta^2)");
  registry.addType<TukeyKernel>("Tukey", "biweight, constant beyond delta");
}

}  // namespace lrsvo
