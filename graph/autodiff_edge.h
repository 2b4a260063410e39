#pragma once

#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "lrsvo/graph/base_edge.h"
#include "lrsvo/graph/dual.h"

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
// The dual numbers are lrsvo's Dual (graph/dual.h) with a fixed-size derivative
// vector as long as the edge's whole tangent space (the sum of its vertices'
// dimensions), so they live on the stack. The duals' values are the residual:
// a linearisation evaluates the residual once, in duals, not again in double.
// Derived classes may still override computeJacobians() with hand-written
// ones; computeAutoDiffJacobians() stays available to check them.
template <typename Derived, int R, typename... Vs>
class AutoDiffEdge : public BaseEdge<R, Vs...> {
  using Base = BaseEdge<R, Vs...>;

 public:
  using typename Base::Residual;
  static constexpr int kTangentDimension = (Vs::kDimension + ...);
  using Dual = lrsvo::Dual<kTangentDimension>;

  void computeResidual(Residual& residual) const override;
  void computeJacobians() override;
  // With the Jacobians by dual numbers, the residual is their values; with
  // Jacobians a derived class writes, it is computeResidual()'s.
  void computeResidualAndJacobians(Residual& residual) override;

  // Fills jacobian<K>() of every non-fixed vertex by dual numbers.
  void computeAutoDiffJacobians();
  // The same, and the residual from the same evaluation.
  void computeAutoDiffResidualAndJacobians(Residual& residual);

  // The same with another forward-mode type DualType: Dual<N> or Eigen's
  // AutoDiffScalar with N derivatives, N = kTangentDimension (the benchmark
  // that compares them uses it).
  template <typename DualType>
  void computeAutoDiffJacobiansWith() {
    differentiate<DualType>(std::make_index_sequence<sizeof...(Vs)>{});
  }

 private:
  // The values of the last dual-number evaluation, and whether they belong to
  // the linearisation under way (computeResidualAndJacobians clears the flag,
  // then learns from it whether computeJacobians() ran the duals).
  Residual dualValues_ = Residual::Zero();
  bool dualValuesFresh_ = false;

  const Derived& derived() const { return static_cast<const Derived&>(*this); }

  // Offset of vertex K's block in the dual numbers' derivative vector.
  template <std::size_t K>
  static constexpr int tangentOffset() {
    constexpr int dimensions[] = {Vs::kDimension...};
    int offset = 0;
    for (std::size_t k = 0; k < K; ++k) offset += dimensions[k];
    return offset;
  }

  template <typename DualType, std::size_t K>
  using DeltaOf = Eigen::Matrix<DualType, Base::template VertexType<static_cast<int>(K)>::kDimension, 1>;

  template <std::size_t... K>
  void evaluateAtStates(Residual& residual, std::index_sequence<K...>) const;
  template <typename DualType, std::size_t K>
  static DeltaOf<DualType, K> seededDelta();
  template <typename DualType, std::size_t... K>
  void differentiate(std::index_sequence<K...>);
  template <typename DualType, std::size_t K>
  void copyJacobian(const Eigen::Matrix<DualType, R, 1>& residual);
};

// The members are defined out of the class so that an edge can compile its
// dual-number code once: its header declares
//   extern template class AutoDiffEdge<EdgeX, R, V0, V1>;
// and its source file instantiates it (template class ...). Without that the
// code is instantiated wherever the edge is constructed, as any template.

template <typename Derived, int R, typename... Vs>
void AutoDiffEdge<Derived, R, Vs...>::computeResidual(Residual& residual) const {
  evaluateAtStates(residual, std::make_index_sequence<sizeof...(Vs)>{});
}

template <typename Derived, int R, typename... Vs>
void AutoDiffEdge<Derived, R, Vs...>::computeJacobians() {
  computeAutoDiffJacobians();
}

template <typename Derived, int R, typename... Vs>
void AutoDiffEdge<Derived, R, Vs...>::computeResidualAndJacobians(Residual& residual) {
  dualValuesFresh_ = false;
  this->computeJacobians();  // virtual: a derived class's own, or the duals
  if (dualValuesFresh_)
    residual = dualValues_;
  else
    computeResidual(residual);
}

template <typename Derived, int R, typename... Vs>
void AutoDiffEdge<Derived, R, Vs...>::computeAutoDiffJacobians() {
  differentiate<Dual>(std::make_index_sequence<sizeof...(Vs)>{});
}

template <typename Derived, int R, typename... Vs>
void AutoDiffEdge<Derived, R, Vs...>::computeAutoDiffResidualAndJacobians(Residual& residual) {
  computeAutoDiffJacobians();
  residual = dualValues_;
}

template <typename Derived, int R, typename... Vs>
template <std::size_t... K>
void AutoDiffEdge<Derived, R, Vs...>::evaluateAtStates(Residual& residual, std::index_sequence<K...>) const {
  derived().residual(this->template vertexAs<static_cast<int>(K)>()->state()..., residual);
}

// Vertex K's update as dual numbers: value 0, derivative the unit vector of its slot.
template <typename Derived, int R, typename... Vs>
template <typename DualType, std::size_t K>
auto AutoDiffEdge<Derived, R, Vs...>::seededDelta() -> DeltaOf<DualType, K> {
  DeltaOf<DualType, K> delta;
  for (int d = 0; d < delta.size(); ++d) {
    if constexpr (std::is_same_v<DualType, Dual>)
      delta[d] = Dual::variable(0.0, tangentOffset<K>() + d);
    else
      delta[d] = DualType(0.0, kTangentDimension, tangentOffset<K>() + d);
  }
  return delta;
}

template <typename Derived, int R, typename... Vs>
template <typename DualType, std::size_t... K>
void AutoDiffEdge<Derived, R, Vs...>::differentiate(std::index_sequence<K...>) {
  Eigen::Matrix<DualType, R, 1> residual;
  // The perturbed states are temporaries bound to the residual's reference
  // parameters: no copy of their derivative vectors.
  derived().residual(this->template vertexAs<static_cast<int>(K)>()->perturbed(seededDelta<DualType, K>())...,
                     residual);
  (copyJacobian<DualType, K>(residual), ...);
  for (int row = 0; row < R; ++row) dualValues_[row] = residual[row].value();
  dualValuesFresh_ = true;
}

template <typename Derived, int R, typename... Vs>
template <typename DualType, std::size_t K>
void AutoDiffEdge<Derived, R, Vs...>::copyJacobian(const Eigen::Matrix<DualType, R, 1>& residual) {
  if (this->vertex(static_cast<int>(K))->fixed()) return;
  constexpr int D = Base::template VertexType<static_cast<int>(K)>::kDimension;
  auto& jacobian = this->template jacobian<static_cast<int>(K)>();
  for (int row = 0; row < R; ++row)
    jacobian.row(row) = residual[row].derivatives().template segment<D>(tangentOffset<K>()).transpose();
}

}  // namespace lrsvo
