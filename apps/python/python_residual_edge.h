#pragma once

#include <memory>
#include <vector>

#include <pybind11/pybind11.h>
#include <Eigen/Core>

#include "lrsvo/graph/edge.h"
#include "lrsvo/graph/robust_kernel.h"

namespace lrsvo::python {

// A least-squares edge whose residual is a Python callable: f(x_0, ..., x_{n-1})
// of the vertices' estimates (numpy arrays, as Graph.estimate gives them)
// returns the residual (any array-like of `dimension` numbers). Jacobians are
// central differences through each vertex's own update, so it works on every
// vertex type. Each evaluation takes the GIL and calls into Python: for
// prototyping a model, many times slower than a C++ edge (scripts/bench_python.py).
// Hidden, as the pybind11 objects it holds are: it never leaves the module.
class __attribute__((visibility("hidden"))) PythonResidualEdge final : public Edge {
 public:
  static constexpr const char* kTypeTag = "PYTHON_RESIDUAL";

  // Throws lrsvo::Error unless the information is dimension x dimension,
  // symmetric and positive definite.
  PythonResidualEdge(std::vector<Vertex*> vertices, pybind11::function residual, int dimension,
                     const Eigen::MatrixXd& information, std::shared_ptr<RobustKernel> kernel);
  ~PythonResidualEdge() override;

  int vertexCount() const override { return static_cast<int>(vertices_.size()); }
  int residualDimension() const override { return dimension_; }
  const char* typeTag() const override { return kTypeTag; }
  bool acceptsVertex(int, const Vertex&) const override { return true; }

  double cost() const override;
  double linearize() override;
  void addHessianBlock(int a, int b, double* block, int ld) const override;
  void addGradient(int a, double* gradient) const override;
  void addSecondDirectionalGradient(double h, const double* const* steps, double* const* gradients) const override;
  // A Python callable has no text form: graph files cannot hold this edge.
  void writeData(std::ostream& out) const override;
  void readData(std::istream& in) override;

 private:
  // The residual at the vertices' estimates, vertex `replaced` read from `stand_in` instead.
  Eigen::VectorXd evaluate(int replaced = -1, const Vertex* standIn = nullptr) const;
  Eigen::VectorXd whiten(const Eigen::VectorXd& r) const { return sqrtInformation_ * r; }
  double robustify(double s, double* weight) const;

  pybind11::function residual_;
  int dimension_;
  Eigen::MatrixXd sqrtInformation_;
  std::shared_ptr<RobustKernel> kernel_;
  // After linearize(): whitened, kernel-weighted residual and Jacobians.
  Eigen::VectorXd whitenedResidual_;
  std::vector<Eigen::MatrixXd> jacobians_;
  double kernelScale_ = 1.0;  // sqrt(rho') at the last linearisation
};

}  // namespace lrsvo::python
