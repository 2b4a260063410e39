#pragma once

#include <cmath>
#include <limits>

#include <Eigen/Core>

namespace lrsvo {

// A forward-mode dual number: a value a and its derivatives v with respect
// to N variables, f(a + v eps) = f(a) + f'(a) v eps with eps^2 = 0. Every
// operation updates v in one fixed-size Eigen expression, evaluated at once,
// so a chain of operations never rebuilds derivative expressions (docs/autodiff.md
// compares it with Eigen's AutoDiffScalar). Constants are Duals with v = 0.
//
// Like a double, a default-initialised Dual (`Dual x;`, the elements of a new
// Eigen matrix) leaves its derivatives unset until assigned: zeroing them would
// cost as much as an operation, for every temporary of every expression.
// Value-initialisation (`Dual()`, `T(0.0)`) is zero.
template <int N>
struct Dual {
  using Derivatives = Eigen::Matrix<double, N, 1>;

  double a = 0.0;
  Derivatives v;

  Dual() = default;
  // Implicit, so constants mix with duals in a residual's expressions.
  Dual(double value) : a(value), v(Derivatives::Zero()) {}
  // Takes any Eigen expression of the derivatives and evaluates it into v directly.
  template <typename Expression>
  Dual(double value, const Eigen::MatrixBase<Expression>& derivatives) : a(value), v(derivatives) {}
  // The variable of slot k: value x, derivative the unit vector e_k.
  static Dual variable(double x, int k) {
    Dual d(x);
    d.v[k] = 1.0;
    return d;
  }

  double value() const { return a; }
  const Derivatives& derivatives() const { return v; }

  Dual& operator+=(const Dual& y) {
    a += y.a;
    v += y.v;
    return *this;
  }
  Dual& operator-=(const Dual& y) {
    a -= y.a;
    v -= y.v;
    return *this;
  }
  Dual& operator*=(const Dual& y) {
    v = v * y.a + y.v * a;
    a *= y.a;
    return *this;
  }
  Dual& operator/=(const Dual& y) {
    a /= y.a;
    v = (v - a * y.v) * (1.0 / y.a);
    return *this;
  }
  Dual& operator+=(double s) {
    a += s;
    return *this;
  }
  Dual& operator-=(double s) {
    a -= s;
    return *this;
  }
  Dual& operator*=(double s) {
    a *= s;
    v *= s;
    return *this;
  }
  Dual& operator/=(double s) {
    a /= s;
    v *= 1.0 / s;
    return *this;
  }
};

template <int N>
Dual<N> operator-(const Dual<N>& x) {
  return Dual<N>(-x.a, -x.v);
}
template <int N>
Dual<N> operator+(const Dual<N>& x) {
  return x;
}

template <int N>
Dual<N> operator+(const Dual<N>& x, const Dual<N>& y) {
  return Dual<N>(x.a + y.a, x.v + y.v);
}
template <int N>
Dual<N> operator+(const Dual<N>& x, double s) {
  return Dual<N>(x.a + s, x.v);
}
template <int N>
Dual<N> operator+(double s, const Dual<N>& x) {
  return Dual<N>(s + x.a, x.v);
}

template <int N>
Dual<N> operator-(const Dual<N>& x, const Dual<N>& y) {
  return Dual<N>(x.a - y.a, x.v - y.v);
}
template <int N>
Dual<N> operator-(const Dual<N>& x, double s) {
  return Dual<N>(x.a - s, x.v);
}
template <int N>
Dual<N> operator-(double s, const Dual<N>& x) {
  return Dual<N>(s - x.a, -x.v);
}

template <int N>
Dual<N> operator*(const Dual<N>& x, const Dual<N>& y) {
  return Dual<N>(x.a * y.a, x.v * y.a + y.v * x.a);
}
template <int N>
Dual<N> operator*(const Dual<N>& x, double s) {
  return Dual<N>(x.a * s, x.v * s);
}
template <int N>
Dual<N> operator*(double s, const Dual<N>& x) {
  return Dual<N>(s * x.a, s * x.v);
}

// (x / y)' = (x' - (x / y) y') / y. Values are divided as in double, so a
// residual's value is the same in duals as in double, bit for bit.
template <int N>
Dual<N> operator/(const Dual<N>& x, const Dual<N>& y) {
  const double quotient = x.a / y.a;
  return Dual<N>(quotient, (x.v - quotient * y.v) * (1.0 / y.a));
}
template <int N>
Dual<N> operator/(const Dual<N>& x, double s) {
  return Dual<N>(x.a / s, x.v * (1.0 / s));
}
// (s / y)' = -(s / y) y' / y
template <int N>
Dual<N> operator/(double s, const Dual<N>& y) {
  const double quotient = s / y.a;
  return Dual<N>(quotient, y.v * (-quotient / y.a));
}

// Comparisons look at the values only, as branches in a residual do.
#define LRSVO_DUAL_COMPARISON(op)                        \
  template <int N>                                       \
  bool operator op(const Dual<N>& x, const Dual<N>& y) { \
    return x.a op y.a;                                   \
  }                                                      \
  template <int N>                                       \
  bool operator op(const Dual<N>& x, double s) {         \
    return x.a op s;                                     \
  }                                                      \
  template <int N>                                       \
  bool operator op(double s, const Dual<N>& y) {         \
    return s op y.a;                                     \
  }
LRSVO_DUAL_COMPARISON(<)
LRSVO_DUAL_COMPARISON(<=)
LRSVO_DUAL_COMPARISON(>)
LRSVO_DUAL_COMPARISON(>=)
LRSVO_DUAL_COMPARISON(==)
LRSVO_DUAL_COMPARISON(!=)
#undef LRSVO_DUAL_COMPARISON

// Whether T is a Dual: special functions written for any scalar take a shorter
// path for duals.
template <typename T>
inline constexpr bool kIsDual = false;
template <int N>
inline constexpr bool kIsDual<Dual<N>> = true;

// A function of x whose value f and derivative df = f'(x) are known in closed
// form: the dual f + df x'. Special functions written for any scalar use it to
// give duals their derivative in one step (vertices/so3.h).
template <int N>
Dual<N> chainRule(double f, double df, const Dual<N>& x) {
  return Dual<N>(f, x.v * df);
}

// The elementary functions, each f(x) with derivative f'(x) x'. They are found
// by argument-dependent lookup beside the std:: overloads for double.
template <int N>
Dual<N> sqrt(const Dual<N>& x) {
  const double root = std::sqrt(x.a);
  return Dual<N>(root, x.v * (0.5 / root));
}
template <int N>
Dual<N> exp(const Dual<N>& x) {
  const double e = std::exp(x.a);
  return Dual<N>(e, x.v * e);
}
template <int N>
Dual<N> log(const Dual<N>& x) {
  return Dual<N>(std::log(x.a), x.v * (1.0 / x.a));
}
template <int N>
Dual<N> sin(const Dual<N>& x) {
  return Dual<N>(std::sin(x.a), x.v * std::cos(x.a));
}
template <int N>
Dual<N> cos(const Dual<N>& x) {
  return Dual<N>(std::cos(x.a), x.v * -std::sin(x.a));
}
template <int N>
Dual<N> tan(const Dual<N>& x) {
  const double t = std::tan(x.a);
  return Dual<N>(t, x.v * (1.0 + t * t));
}
template <int N>
Dual<N> atan(const Dual<N>& x) {
  return Dual<N>(std::atan(x.a), x.v * (1.0 / (1.0 + x.a * x.a)));
}
template <int N>
Dual<N> asin(const Dual<N>& x) {
  return Dual<N>(std::asin(x.a), x.v * (1.0 / std::sqrt(1.0 - x.a * x.a)));
}
template <int N>
Dual<N> acos(const Dual<N>& x) {
  return Dual<N>(std::acos(x.a), x.v * (-1.0 / std::sqrt(1.0 - x.a * x.a)));
}
// atan2(y, x)' = (x y' - y x') / (x^2 + y^2)
template <int N>
Dual<N> atan2(const Dual<N>& y, const Dual<N>& x) {
  const double inverse = 1.0 / (x.a * x.a + y.a * y.a);
  return Dual<N>(std::atan2(y.a, x.a), (y.v * x.a - x.v * y.a) * inverse);
}
template <int N>
Dual<N> atan2(const Dual<N>& y, double x) {
  return atan2(y, Dual<N>(x));
}
template <int N>
Dual<N> atan2(double y, const Dual<N>& x) {
  return atan2(Dual<N>(y), x);
}
template <int N>
Dual<N> pow(const Dual<N>& x, double p) {
  return Dual<N>(std::pow(x.a, p), x.v * (p * std::pow(x.a, p - 1.0)));
}
// |x|' = sign(x) x' (0 at x = 0: either one-sided derivative would be arbitrary).
template <int N>
Dual<N> abs(const Dual<N>& x) {
  return x.a < 0.0 ? -x : (x.a > 0.0 ? x : Dual<N>(0.0));
}
template <int N>
bool isfinite(const Dual<N>& x) {
  return std::isfinite(x.a) && x.v.allFinite();
}

}  // namespace lrsvo

namespace Eigen {

// What Eigen needs to hold duals in its matrices and quaternions.
template <int N>
struct NumTraits<lrsvo::Dual<N>> {
  using Real = lrsvo::Dual<N>;
  using NonInteger = lrsvo::Dual<N>;
  using Nested = lrsvo::Dual<N>;
  using Literal = lrsvo::Dual<N>;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 1 + N,
    AddCost = 1 + N,
    MulCost = 1 + 2 * N,
  };
  static int digits10() { return NumTraits<double>::digits10(); }
  static lrsvo::Dual<N> epsilon() { return lrsvo::Dual<N>(NumTraits<double>::epsilon()); }
  static lrsvo::Dual<N> dummy_precision() { return lrsvo::Dual<N>(NumTraits<double>::dummy_precision()); }
  static lrsvo::Dual<N> highest() { return lrsvo::Dual<N>(NumTraits<double>::highest()); }
  static lrsvo::Dual<N> lowest() { return lrsvo::Dual<N>(NumTraits<double>::lowest()); }
  static lrsvo::Dual<N> infinity() { return lrsvo::Dual<N>(NumTraits<double>::infinity()); }
  static lrsvo::Dual<N> quiet_NaN() { return lrsvo::Dual<N>(NumTraits<double>::quiet_NaN()); }
};

// Products and sums of dual and double matrices are dual.
template <int N, typename BinaryOp>
struct ScalarBinaryOpTraits<lrsvo::Dual<N>, double, BinaryOp> {
  using ReturnType = lrsvo::Dual<N>;
};
template <int N, typename BinaryOp>
struct ScalarBinaryOpTraits<double, lrsvo::Dual<N>, BinaryOp> {
  using ReturnType = lrsvo::Dual<N>;
};

}  // namespace Eigen
