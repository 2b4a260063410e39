#pragma once

#include <Eigen/Core>

// Small dense products on H's column-major blocks, with fixed-size paths for
// the shapes of bundle adjustment (cameras of 9 or poses of 6, points of 3);
// any other shape takes Eigen's dynamic ones. Always inlined: they run once per
// block in the solvers' innermost loops, where a call (through the shared
// library's PLT) costs as much as the product.
namespace lrsvo::kernels {

template <int R, int C>
using BlockMap = Eigen::Map<const Eigen::Matrix<double, R, C>>;

// y += sign A x, or y += sign A^T x, for a rows x cols block A.
template <int R, int C, bool Transposed>
[[gnu::always_inline]] inline void accumulate(const double* a, const double* x, double* y, int rows, int cols,
                                              double sign) {
  using InVector = Eigen::Map<const Eigen::Matrix<double, Transposed ? R : C, 1>>;
  using OutVector = Eigen::Map<Eigen::Matrix<double, Transposed ? C : R, 1>>;
  if constexpr (Transposed)
    OutVector(y, cols).noalias() += sign * (BlockMap<R, C>(a, rows, cols).transpose() * InVector(x, rows));
  else
    OutVector(y, rows).noalias() += sign * (BlockMap<R, C>(a, rows, cols) * InVector(x, cols));
}

template <bool Transposed>
[[gnu::always_inline]] inline void accumulateBlock(const double* a, const double* x, double* y, int rows, int cols,
                                                   double sign) {
  constexpr int X = Eigen::Dynamic;
  if (cols == 3 && rows == 9) return accumulate<9, 3, Transposed>(a, x, y, rows, cols, sign);
  if (cols == 3 && rows == 6) return accumulate<6, 3, Transposed>(a, x, y, rows, cols, sign);
  if (cols == 9 && rows == 9) return accumulate<9, 9, Transposed>(a, x, y, rows, cols, sign);
  if (cols == 6 && rows == 6) return accumulate<6, 6, Transposed>(a, x, y, rows, cols, sign);
  accumulate<X, X, Transposed>(a, x, y, rows, cols, sign);
}

// d -= W V W^T for a rows x cols block W and a cols x cols block V.
template <int R, int C>
[[gnu::always_inline]] inline void subtractCongruence(const double* w, const double* v, double* d, int rows, int cols) {
  const BlockMap<R, C> wm(w, rows, cols);
  Eigen::Map<Eigen::Matrix<double, R, R>>(d, rows, rows).noalias() -=
      wm * BlockMap<C, C>(v, cols, cols) * wm.transpose();
}

[[gnu::always_inline]] inline void subtractCongruence(const double* w, const double* v, double* d, int rows, int cols) {
  constexpr int X = Eigen::Dynamic;
  if (cols == 3 && rows == 9) return subtractCongruence<9, 3>(w, v, d, rows, cols);
  if (cols == 3 && rows == 6) return subtractCongruence<6, 3>(w, v, d, rows, cols);
  subtractCongruence<X, X>(w, v, d, rows, cols);
}

}  // namespace lrsvo::kernels
