#pragma once

#include <cmath>
#include <iomanip>
#include <istream>
#include <limits>
#include <memory>
#include <ostream>
#include <string>

#include <Eigen/Core>

#include "lrsvo/graph/error.h"
#include "lrsvo/graph/robust_kernel.h"

// Reading and writing the numbers of an edge's data in graph files. Values are
// written with max_digits10 so that a save/load round trip is exact.
namespace lrsvo {

inline void writeNumber(std::ostream& out, double value) {
  out << ' ' << std::setprecision(std::numeric_limits<double>::max_digits10) << value;
}

// Reads one finite number; throws naming `what` otherwise.
inline double readNumber(std::istream& in, const char* what) {
  double value;
  if (!(in >> value)) throw Error(std::string(what) + ": missing or malformed number");
  if (!std::isfinite(value)) throw Error(std::string(what) + ": value is not finite");
  return value;
}

template <typename Derived>
void writeVector(std::ostream& out, const Eigen::MatrixBase<Derived>& v) {
  for (Eigen::Index i = 0; i < v.size(); ++i) writeNumber(out, v[i]);
}

template <typename Derived>
void readVector(std::istream& in, Eigen::MatrixBase<Derived>& v, const char* what) {
  for (Eigen::Index i = 0; i < v.size(); ++i) v[i] = readNumber(in, what);
}

template <typename Derived>
void writeUpperTriangle(std::ostream& out, const Eigen::MatrixBase<Derived>& m) {
  for (Eigen::Index r = 0; r < m.rows(); ++r)
    for (Eigen::Index c = r; c < m.cols(); ++c) writeNumber(out, m(r, c));
}

template <typename Derived>
void readUpperTriangle(std::istream& in, Eigen::MatrixBase<Derived>& m, const char* what) {
  for (Eigen::Index r = 0; r < m.rows(); ++r)
    for (Eigen::Index c = r; c < m.cols(); ++c) m(r, c) = m(c, r) = readNumber(in, what);
}

// "NONE" or "<kernel name> <delta>".
inline void writeKernel(std::ostream& out, const RobustKernel* kernel) {
  if (!kernel) {
    out << " NONE";
    return;
  }
  out << ' ' << kernel->name();
  writeNumber(out, kernel->delta());
}

inline std::shared_ptr<RobustKernel> readKernel(std::istream& in, const char* what) {
  std::string name;
  if (!(in >> name)) throw Error(std::string(what) + ": missing robust kernel (NONE or name delta)");
  if (name == "NONE") return nullptr;
  const double delta = readNumber(in, what);
  return makeRobustKernel(name, delta);
}

}  // namespace lrsvo
