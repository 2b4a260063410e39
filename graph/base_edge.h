#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <istream>
#include <memory>
#include <ostream>
#include <tuple>
#include <utility>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "lrsvo/graph/edge.h"
#include "lrsvo/graph/edge_io.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/numeric_diff.h"
#include "lrsvo/graph/robust_kernel.h"

namespace lrsvo {

// A least-squares edge with an R-dimensional residual over vertices Vs...
// (each a BaseVertex<D>). Derived classes give computeResidual() and, for
// speed and accuracy, computeJacobians() (or derive from AutoDiffEdge); the
// default Jacobians are numeric differences (graph/numeric_diff.h).
// The cost is 1/2 rho(r^T Omega r); blocks use whitened, kernel-weighted
// Jacobians (IRLS: H = rho' J^T Omega J, g = rho' J^T Omega r).
template <int R, typename... Vs>
class BaseEdge : public Edge {
 public:
  static constexpr int kResidualDim = R;
  static constexpr int kVertexCount = sizeof...(Vs);
  using Residual = Eigen::Matrix<double, R, 1>;
  using Information = Eigen::Matrix<double, R, R>;
  template <int K>
  using VertexType = std::tuple_element_t<K, std::tuple<Vs...>>;
  template <int K>
  using Jacobian = Eigen::Matrix<double, R, VertexType<K>::kDimension>;

  BaseEdge() {
    vertices_.assign(kVertexCount, nullptr);
    std::apply([](auto&... jacobian) { (jacobian.setZero(), ...); }, jacobians_);
  }

  int vertexCount() const final { return kVertexCount; }
  int residualDimension() const final { return R; }
  bool acceptsVertex(int k, const Vertex& vertex) const final { return kAcceptTable[k](vertex); }

  template <int K>
  VertexType<K>* vertexAs() const {
    return static_cast<VertexType<K>*>(vertices_[K]);
  }

  const Residual& measurement() const { return measurement_; }
  void setMeasurement(const Residual& measurement) { measurement_ = measurement; }

  const Information& information() const { return information_; }
  // Throws unless the matrix is symmetric positive definite and finite.
  void setInformation(const Information& information) {
    if (!information.allFinite() || !information.isApprox(information.transpose()))
      throw Error(std::string(typeTag()) + ": information matrix is not finite and symmetric");
    Eigen::LLT<Information> llt(information);
    if (llt.info() != Eigen::Success)
      throw Error(std::string(typeTag()) + ": information matrix is not positive definite");
    information_ = information;
    sqrtInformation_ = llt.matrixU();
    identityInformation_ = information.isIdentity(0.0);
  }

  const std::shared_ptr<RobustKernel>& robustKernel() const { return kernel_; }
  void setRobustKernel(std::shared_ptr<RobustKernel> kernel) { kernel_ = std::move(kernel); }

  // r = prediction - measurement (not whitened).
  virtual void computeResidual(Residual& residual) const = 0;

  // Fills jacobian<K>() = d r / d delta_K for every non-fixed vertex K.
  virtual void computeJacobians() { computeNumericJacobians(); }

  // r and every Jacobian, as linearize() needs them: computeResidual(), then
  // computeJacobians(). Edges that get both from one evaluation override it.
  virtual void computeResidualAndJacobians(Residual& residual) {
    computeResidual(residual);
    computeJacobians();
  }

  // Numeric differences through each vertex's oplus, on private copies of the
  // vertices (safe while other edges are evaluated), by numericDiffOptions().
  // The fallback, and the reference that tests check analytic Jacobians against.
  void computeNumericJacobians() { numericJacobians(std::make_index_sequence<kVertexCount>{}); }

  // How this edge type differentiates numerically; central differences with
  // relative steps unless a derived type says otherwise.
  virtual NumericDiffOptions numericDiffOptions() const { return {}; }

  template <int K>
  Jacobian<K>& jacobian() {
    return std::get<K>(jacobians_);
  }
  template <int K>
  const Jacobian<K>& jacobian() const {
    return std::get<K>(jacobians_);
  }

  double cost() const override {
    Residual r;
    computeResidual(r);
    return 0.5 * robustify(whiten(r).squaredNorm(), nullptr);
  }

  double linearize() override {
    computeResidualAndJacobians(whitenedResidual_);
    double weight = 1.0;
    whitenedResidual_ = whiten(whitenedResidual_);
    const double rho = robustify(whitenedResidual_.squaredNorm(), &weight);
    // Fold sqrt(rho') and the square-root information into residual and
    // Jacobians once, so each block is a plain J_a^T J_b.
    kernelScale_ = std::sqrt(weight);
    whitenedResidual_ *= kernelScale_;
    whitenJacobians(kernelScale_, std::make_index_sequence<kVertexCount>{});
    return 0.5 * rho;
  }

  void addSecondDirectionalGradient(double h, const double* const* steps, double* const* gradients) const override {
    Residual moved;
    computeResidual(moved);
    const Residual alongStep = jacobianTimes(steps, std::make_index_sequence<kVertexCount>{});
    const Residual second = (2.0 / h) * ((kernelScale_ * whiten(moved) - whitenedResidual_) / h - alongStep);
    addJacobianTransposeTimes(second, gradients, std::make_index_sequence<kVertexCount>{});
  }

  void addHessianBlock(int a, int b, double* block, int ld) const final { kBlockTable[a][b](*this, block, ld); }
  void addGradient(int a, double* gradient) const final { kGradientTable[a](*this, gradient); }

  void writeData(std::ostream& out) const override {
    writeParameters(out);
    writeVector(out, measurement_);
    writeUpperTriangle(out, information_);
    writeKernel(out, kernel_.get());
  }
  void readData(std::istream& in) override {
    readParameters(in);
    Residual z;
    readVector(in, z, typeTag());
    Information info;
    readUpperTriangle(in, info, typeTag());
    setMeasurement(z);
    setInformation(info);
    kernel_ = readKernel(in, typeTag());
  }

 protected:
  // Edge-type data that precedes the measurement in graph files (intrinsics, ...).
  virtual void writeParameters(std::ostream&) const {}
  virtual void readParameters(std::istream&) {}

  Residual measurement_ = Residual::Zero();

 private:
  using BlockFn = void (*)(const BaseEdge&, double*, int);
  using GradientFn = void (*)(const BaseEdge&, double*);
  using AcceptFn = bool (*)(const Vertex&);

  template <int K>
  static bool acceptImpl(const Vertex& vertex) {
    return dynamic_cast<const VertexType<K>*>(&vertex) != nullptr;
  }
  template <std::size_t... K>
  static constexpr std::array<AcceptFn, kVertexCount> acceptTable(std::index_sequence<K...>) {
    return {&acceptImpl<static_cast<int>(K)>...};
  }
  static constexpr auto kAcceptTable = acceptTable(std::make_index_sequence<kVertexCount>{});

  Residual whiten(const Residual& r) const { return identityInformation_ ? r : Residual(sqrtInformation_ * r); }

  double robustify(double s, double* weight) const {
    if (!kernel_) {
      if (weight) *weight = 1.0;
      return s;
    }
    double w = 1.0;
    const double rho = kernel_->evaluate(s, &w);
    if (weight) *weight = w;
    return rho;
  }

  template <std::size_t... K>
  void whitenJacobians(double scale, std::index_sequence<K...>) {
    if (identityInformation_)
      ((std::get<K>(jacobians_) *= scale), ...);
    else
      ((std::get<K>(jacobians_) = scale * sqrtInformation_ * std::get<K>(jacobians_)), ...);
  }

  // J v from each vertex's part of v (null: no block, no term).
  template <std::size_t... K>
  Residual jacobianTimes(const double* const* steps, std::index_sequence<K...>) const {
    Residual product = Residual::Zero();
    ((steps[K]
          ? void(product.noalias() += std::get<K>(jacobians_) *
                                      Eigen::Map<const Eigen::Matrix<double, VertexType<K>::kDimension, 1>>(steps[K]))
          : void()),
     ...);
    return product;
  }

  template <std::size_t... K>
  void addJacobianTransposeTimes(const Residual& w, double* const* gradients, std::index_sequence<K...>) const {
    ((gradients[K] ? void(Eigen::Map<Eigen::Matrix<double, VertexType<K>::kDimension, 1>>(gradients[K]).noalias() +=
                          std::get<K>(jacobians_).transpose() * w)
                   : void()),
     ...);
  }

  template <std::size_t... K>
  void numericJacobians(std::index_sequence<K...>) {
    const NumericDiffOptions options = numericDiffOptions();
    Residual r0 = Residual::Zero();
    if (options.method == NumericDifference::kForward) computeResidual(r0);
    (numericJacobian<K>(options, r0), ...);
  }

  // Differentiates on a private copy of the vertex, so concurrent edges never
  // see a perturbed shared vertex. The step of coordinate d is the options'
  // relative step times max(|x_d|, typical magnitude) for Euclidean vertices
  // (whose coordinate d is parameter d), times the typical magnitude (1 when
  // that is 0) for manifold vertices' tangent coordinates.
  template <int K>
  void numericJacobian(const NumericDiffOptions& options, const Residual& r0) {
    Vertex* original = vertices_[K];
    if (original->fixed()) return;
    constexpr int D = VertexType<K>::kDimension;
    std::unique_ptr<Vertex> copy = original->clone();
    Eigen::VectorXd start(copy->estimateSize());
    copy->getEstimate(start.data());
    vertices_[K] = copy.get();
    const double relativeStep = options.step();
    for (int d = 0; d < D; ++d) {
      const double magnitude = std::max(original->isEuclidean() ? std::abs(start[d]) : 0.0, options.typicalMagnitude);
      const double h = relativeStep * (magnitude > 0.0 ? magnitude : 1.0);
      auto evaluate = [&](double t, Residual& residual) {
        Eigen::Matrix<double, D, 1> delta = Eigen::Matrix<double, D, 1>::Zero();
        delta[d] = t;
        copy->setEstimate(start.data());
        copy->oplus(delta.data());
        computeResidual(residual);
      };
      std::get<K>(jacobians_).col(d) = numericDerivative(evaluate, r0, h, options.method);
    }
    vertices_[K] = original;
  }

  template <int A, int B>
  static void blockImpl(const BaseEdge& edge, double* block, int ld) {
    using Block = Eigen::Matrix<double, VertexType<A>::kDimension, VertexType<B>::kDimension>;
    // lazyProduct keeps small fixed-size blocks out of Eigen's large-matrix GEMM path.
    const auto product = std::get<A>(edge.jacobians_).transpose().lazyProduct(std::get<B>(edge.jacobians_));
    if (ld == Block::RowsAtCompileTime) {  // a block stored on its own (BlockSystem): vectorised
      Eigen::Map<Block>(block).noalias() += product;
    } else {
      Eigen::Map<Block, 0, Eigen::OuterStride<>>(block, Block::RowsAtCompileTime, Block::ColsAtCompileTime,
                                                 Eigen::OuterStride<>(ld))
          .noalias() += product;
    }
  }

  template <int A>
  static void gradientImpl(const BaseEdge& edge, double* gradient) {
    using Gradient = Eigen::Matrix<double, VertexType<A>::kDimension, 1>;
    Eigen::Map<Gradient>(gradient).noalias() += std::get<A>(edge.jacobians_).transpose() * edge.whitenedResidual_;
  }

  template <int A, std::size_t... B>
  static constexpr std::array<BlockFn, kVertexCount> blockRow(std::index_sequence<B...>) {
    return {&blockImpl<A, static_cast<int>(B)>...};
  }
  template <std::size_t... A>
  static constexpr std::array<std::array<BlockFn, kVertexCount>, kVertexCount> blockTable(std::index_sequence<A...>) {
    return {blockRow<static_cast<int>(A)>(std::make_index_sequence<kVertexCount>{})...};
  }
  template <std::size_t... A>
  static constexpr std::array<GradientFn, kVertexCount> gradientTable(std::index_sequence<A...>) {
    return {&gradientImpl<static_cast<int>(A)>...};
  }

  static constexpr auto kBlockTable = blockTable(std::make_index_sequence<kVertexCount>{});
  static constexpr auto kGradientTable = gradientTable(std::make_index_sequence<kVertexCount>{});

  Information information_ = Information::Identity();
  Information sqrtInformation_ = Information::Identity();
  bool identityInformation_ = true;
  std::shared_ptr<RobustKernel> kernel_;
  std::tuple<Eigen::Matrix<double, R, Vs::kDimension>...> jacobians_;
  Residual whitenedResidual_ = Residual::Zero();
  double kernelScale_ = 1.0;  // sqrt(rho') at the last linearisation
};

}  // namespace lrsvo
