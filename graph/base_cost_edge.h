#pragma once

#include <array>
#include <ostream>
#include <tuple>
#include <utility>

#include <Eigen/Core>

#include "lrsvo/graph/edge.h"

namespace lrsvo {

// An edge that is not a squared residual: it gives its value, gradient and
// Hessian directly (a log barrier, say). They enter the normal equations as
// they are, and the value enters the cost that LM's gain ratio uses.
template <typename... Vs>
class BaseCostEdge : public Edge {
 public:
  static constexpr int kVertexCount = sizeof...(Vs);
  static constexpr int kDimension = (Vs::kDimension + ...);
  using Gradient = Eigen::Matrix<double, kDimension, 1>;
  using Hessian = Eigen::Matrix<double, kDimension, kDimension>;
  template <int K>
  using VertexType = std::tuple_element_t<K, std::tuple<Vs...>>;

  BaseCostEdge() { vertices_.assign(kVertexCount, nullptr); }
  int vertexCount() const final { return kVertexCount; }
  bool acceptsVertex(int k, const Vertex& vertex) const final { return kAcceptTable[k](vertex); }

  template <int K>
  VertexType<K>* vertexAs() const {
    return static_cast<VertexType<K>*>(vertices_[K]);
  }

  // Value of the term; +inf where it is undefined (outside a barrier's box).
  double cost() const override = 0;
  // Gradient and Hessian with respect to the stacked updates of all vertices.
  virtual void computeGradientHessian(Gradient& gradient, Hessian& hessian) const = 0;

  double linearize() override {
    computeGradientHessian(gradient_, hessian_);
    return cost();
  }
  void addHessianBlock(int a, int b, double* block, int ld) const final {
    const int da = vertices_[a]->dimension();
    const int db = vertices_[b]->dimension();
    Eigen::Map<Eigen::MatrixXd, 0, Eigen::OuterStride<>> target(block, da, db, Eigen::OuterStride<>(ld));
    target += hessian_.block(kOffsets[a], kOffsets[b], da, db);
  }
  void addGradient(int a, double* gradient) const final {
    const int da = vertices_[a]->dimension();
    Eigen::Map<Eigen::VectorXd>(gradient, da) += gradient_.segment(kOffsets[a], da);
  }

 private:
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

  static constexpr std::array<int, kVertexCount> offsets() {
    std::array<int, kVertexCount> result{};
    const std::array<int, kVertexCount> dims{Vs::kDimension...};
    for (int k = 1; k < kVertexCount; ++k) result[k] = result[k - 1] + dims[k - 1];
    return result;
  }
  static constexpr std::array<int, kVertexCount> kOffsets = offsets();

  Gradient gradient_ = Gradient::Zero();
  Hessian hessian_ = Hessian::Zero();
};

}  // namespace lrsvo
