#pragma once

#include <tuple>
#include <utility>

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "lrsvo/graph/base_edge.h"

namespace lrsvo {

// A least-squares edge whose Jacobians come from forward-mode automatic
// differentiation: the derived class writes its residual once, templated on
// the scalar,
//
//   template <typename T>
//   void residual(const State0<T>& v0, const State1<T>& v1, ..., Eigen::Matrix<T, R, 1>& r) const;
//
// where vertex K's state is whatever VertexType<K>::state() and perturbed<T>()
// return (VectorVertex: its vector; VertexPose: rotation and translation). The
// residual is evaluated in double at each vertex's state(), and differentiated
// with dual numbers through each vertex's update at zero: J_K = d r(x_K [+] delta_K) / d delta_K
// at delta_K = 0, exact to rounding for manifold vertices too. A vertex type is
// usable here once it provides state() and perturbed<T>(delta) (docs/autodiff.md).
//
// The dual numbers are Eigen's AutoDiffScalar with a fixed-size derivative
// vector as long as the edge's whole tangent space (the sum of its vertices'
// dimensions), so they live on the stack. Derived classes may still override
// computeJacobians() with hand-written ones; computeAutoDiffJacobians() stays
// available to check them.
template <typename Derived, int R, typename... Vs>
class AutoDiffEdge : public BaseEdge<R, Vs...> {
  using Base = BaseEdge<R, Vs...>;

 public:
  using typename Base::Residual;
  static constexpr int kTangentDimension = (Vs::kDimension + ...);
  using Dual = Eigen::AutoDiffScalar<Eigen::Matrix<double, kTangentDimension, 1>>;

  void computeResidual(Residual& residual) const override {
    evaluateAtStates(residual, std::make_index_sequence<sizeof...(Vs)>{});
  }

  void computeJacobians() override { computeAutoDiffJacobians(); }

  // Fills jacobian<K>() of every non-fixed vertex by dual numbers.
  void computeAutoDiffJacobians() { differentiate(std::make_index_sequence<sizeof...(Vs)>{}); }

 private:
  const Derived& derived() const { return static_cast<const Derived&>(*this); }

  template <std::size_t... K>
  void evaluateAtStates(Residual& residual, std::index_sequence<K...>) const {
    derived().residual(this->template vertexAs<static_cast<int>(K)>()->state()..., residual);
  }

  // Offset of vertex K's block in the dual numbers' derivative vector.
  template <std::size_t K>
  static constexpr int tangentOffset() {
    constexpr int dimensions[] = {Vs::kDimension...};
    int offset = 0;
    for (std::size_t k = 0; k < K; ++k) offset += dimensions[k];
    return offset;
  }

  // Vertex K's update as dual numbers: value 0, derivative the unit vector of its slot.
  template <std::size_t K>
  static Eigen::Matrix<Dual, Base::template VertexType<static_cast<int>(K)>::kDimension, 1> seededDelta() {
    constexpr int D = Base::template VertexType<static_cast<int>(K)>::kDimension;
    Eigen::Matrix<Dual, D, 1> delta;
    for (int d = 0; d < D; ++d) delta[d] = Dual(0.0, kTangentDimension, tangentOffset<K>() + d);
    return delta;
  }

  template <std::size_t... K>
  void differentiate(std::index_sequence<K...>) {
    const auto states = std::make_tuple(this->template vertexAs<static_cast<int>(K)>()->perturbed(seededDelta<K>())...);
    Eigen::Matrix<Dual, R, 1> residual;
    derived().residual(std::get<K>(states)..., residual);
    (copyJacobian<K>(residual), ...);
  }

  template <std::size_t K>
  void copyJacobian(const Eigen::Matrix<Dual, R, 1>& residual) {
    if (this->vertex(static_cast<int>(K))->fixed()) return;
    constexpr int D = Base::template VertexType<static_cast<int>(K)>::kDimension;
    auto& jacobian = this->template jacobian<static_cast<int>(K)>();
    for (int row = 0; row < R; ++row)
      jacobian.row(row) = residual[row].derivatives().template segment<D>(tangentOffset<K>()).transpose();
  }
};

}  // namespace lrsvo
