#include "python_residual_edge.h"

#include <cmath>
#include <string>

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <Eigen/Cholesky>

#include "lrsvo/graph/error.h"
#include "lrsvo/graph/numeric_diff.h"

namespace py = pybind11;

namespace lrsvo::python {

PythonResidualEdge::PythonResidualEdge(std::vector<Vertex*> vertices, py::function residual, int dimension,
                                       const Eigen::MatrixXd& information, std::shared_ptr<RobustKernel> kernel)
    : residual_(std::move(residual)), dimension_(dimension), kernel_(std::move(kernel)) {
  if (dimension < 1) throw Error("a Python residual needs a dimension of at least 1");
  if (vertices.empty()) throw Error("a Python residual needs at least one vertex");
  if (information.rows() != dimension || information.cols() != dimension)
    throw Error("a Python residual of dimension " + std::to_string(dimension) + " needs a " +
                std::to_string(dimension) + " x " + std::to_string(dimension) + " information matrix");
  if (!information.allFinite() || !information.isApprox(information.transpose()))
    throw Error("a Python residual's information matrix is not finite and symmetric");
  Eigen::LLT<Eigen::MatrixXd> llt(information);
  if (llt.info() != Eigen::Success) throw Error("a Python residual's information matrix is not positive definite");
  sqrtInformation_ = llt.matrixU();
  vertices_ = std::move(vertices);
  jacobians_.resize(vertices_.size());
}

// The callable may be the last reference to Python objects: release it under the GIL.
PythonResidualEdge::~PythonResidualEdge() {
  py::gil_scoped_acquire gil;
  residual_ = py::function();
}

Eigen::VectorXd PythonResidualEdge::evaluate(int replaced, const Vertex* standIn) const {
  py::gil_scoped_acquire gil;
  py::tuple arguments(vertices_.size());
  for (std::size_t k = 0; k < vertices_.size(); ++k) {
    const Vertex* vertex = static_cast<int>(k) == replaced ? standIn : vertices_[k];
    py::array_t<double> estimate(vertex->estimateSize());
    vertex->getEstimate(estimate.mutable_data());
    arguments[k] = std::move(estimate);
  }
  const py::object value = residual_(*arguments);
  const auto residual = py::cast<Eigen::VectorXd>(py::array_t<double, py::array::forcecast>(value).attr("ravel")());
  if (residual.size() != dimension_)
    throw Error("a Python residual returned " + std::to_string(residual.size()) + " values; its dimension is " +
                std::to_string(dimension_));
  return residual;
}

double PythonResidualEdge::robustify(double s, double* weight) const {
  double w = 1.0;
  const double rho = kernel_ ? kernel_->evaluate(s, &w) : s;
  if (weight) *weight = w;
  return rho;
}

double PythonResidualEdge::cost() const { return 0.5 * robustify(whiten(evaluate()).squaredNorm(), nullptr); }

double PythonResidualEdge::linearize() {
  const Eigen::VectorXd r0 = evaluate();
  const NumericDiffOptions options;  // central differences, relative steps
  for (std::size_t k = 0; k < vertices_.size(); ++k) {
    const Vertex& vertex = *vertices_[k];
    Eigen::MatrixXd& jacobian = jacobians_[k];
    jacobian.setZero(dimension_, vertex.dimension());
    if (vertex.fixed()) continue;
    Eigen::VectorXd start(vertex.estimateSize());
    vertex.getEstimate(start.data());
    std::unique_ptr<Vertex> moved = vertex.clone();
    for (int d = 0; d < vertex.dimension(); ++d) {
      // A Euclidean vertex's coordinate d is parameter d: the step follows its magnitude.
      const double magnitude = vertex.isEuclidean() ? std::max(std::abs(start[d]), options.typicalMagnitude) : 1.0;
      const double h = options.step() * magnitude;
      auto at = [&](double t, Eigen::VectorXd& residual) {
        moved->setEstimate(start.data());
        Eigen::VectorXd delta = Eigen::VectorXd::Zero(vertex.dimension());
        delta[d] = t;
        moved->oplus(delta.data());
        residual = evaluate(static_cast<int>(k), moved.get());
      };
      jacobian.col(d) = numericDerivative(at, r0, h, options.method);
    }
  }
  double weight = 1.0;
  whitenedResidual_ = whiten(r0);
  const double rho = robustify(whitenedResidual_.squaredNorm(), &weight);
  kernelScale_ = std::sqrt(weight);
  whitenedResidual_ *= kernelScale_;
  for (Eigen::MatrixXd& jacobian : jacobians_) jacobian = kernelScale_ * sqrtInformation_ * jacobian;
  return 0.5 * rho;
}

void PythonResidualEdge::addSecondDirectionalGradient(double h, const double* const* steps,
                                                      double* const* gradients) const {
  Eigen::VectorXd alongStep = Eigen::VectorXd::Zero(dimension_);
  for (std::size_t k = 0; k < vertices_.size(); ++k)
    if (steps[k]) alongStep += jacobians_[k] * Eigen::Map<const Eigen::VectorXd>(steps[k], jacobians_[k].cols());
  const Eigen::VectorXd second = (2.0 / h) * ((kernelScale_ * whiten(evaluate()) - whitenedResidual_) / h - alongStep);
  for (std::size_t k = 0; k < vertices_.size(); ++k)
    if (gradients[k])
      Eigen::Map<Eigen::VectorXd>(gradients[k], jacobians_[k].cols()) += jacobians_[k].transpose() * second;
}

void PythonResidualEdge::addHessianBlock(int a, int b, double* block, int ld) const {
  const Eigen::MatrixXd& ja = jacobians_[a];
  const Eigen::MatrixXd& jb = jacobians_[b];
  Eigen::Map<Eigen::MatrixXd, 0, Eigen::OuterStride<>>(block, ja.cols(), jb.cols(), Eigen::OuterStride<>(ld)) +=
      ja.transpose() * jb;
}

void PythonResidualEdge::addGradient(int a, double* gradient) const {
  const Eigen::MatrixXd& ja = jacobians_[a];
  Eigen::Map<Eigen::VectorXd>(gradient, ja.cols()) += ja.transpose() * whitenedResidual_;
}

void PythonResidualEdge::writeData(std::ostream&) const {
  throw Error("a graph with a Python residual cannot be saved: a Python callable has no text form");
}

void PythonResidualEdge::readData(std::istream&) { throw Error("a Python residual cannot be read from a graph file"); }

}  // namespace lrsvo::python
