#include "lrsvo/constraints/bounds.h"

#include <cmath>
#include <string>

#include "lrsvo/graph/error.h"

namespace lrsvo {

void Bounds::set(Vertex* vertex, int index, double lower, double upper) {
  if (!vertex) throw Error("bounds: null vertex");
  const std::string where = "bounds on vertex " + std::to_string(vertex->id()) + " (" + vertex->typeTag() + ")";
  if (!vertex->isEuclidean())
    throw Error(where + ": only Euclidean vertices (oplus = addition) can carry parameter bounds");
  if (index < 0 || index >= vertex->dimension())
    throw Error(where + ": parameter " + std::to_string(index) + " out of range");
  if (!std::isfinite(lower) || !std::isfinite(upper) || !(lower < upper))
    throw Error(where + ": need finite lower < upper, got [" + std::to_string(lower) + ", " + std::to_string(upper) +
                "]");
  for (Bound& bound : bounds_)
    if (bound.vertex == vertex && bound.index == index) {
      bound.lower = lower;
      bound.upper = upper;
      return;
    }
  bounds_.push_back({vertex, index, lower, upper});
}

void Bounds::setAround(Vertex* vertex, const double* centre, const double* tolerance) {
  for (int i = 0; i < vertex->dimension(); ++i) set(vertex, i, centre[i] - tolerance[i], centre[i] + tolerance[i]);
}

double Bounds::value(const Bound& bound) {
  std::vector<double> values(bound.vertex->estimateSize());
  bound.vertex->getEstimate(values.data());
  return values[bound.index];
}

void Bounds::setValue(const Bound& bound, double value) {
  std::vector<double> values(bound.vertex->estimateSize());
  bound.vertex->getEstimate(values.data());
  values[bound.index] = value;
  bound.vertex->setEstimate(values.data());
}

bool Bounds::hold() const {
  for (const Bound& bound : bounds_) {
    const double x = value(bound);
    if (x < bound.lower || x > bound.upper) return false;
  }
  return true;
}

}  // namespace lrsvo
