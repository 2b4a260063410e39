#pragma once

#include <vector>

#include "lrsvo/graph/vertex.h"

namespace lrsvo {

// Box bounds lower < x < upper on scalar parameters of Euclidean vertices
// (VectorVertex: parameter i is coordinate i of the update), e.g. the six
// numbers of a stereo extrinsic or kappa.
class Bounds {
 public:
  struct Bound {
    Vertex* vertex;
    int index;
    double lower;
    double upper;
    double centre() const { return 0.5 * (lower + upper); }
    double halfWidth() const { return 0.5 * (upper - lower); }
  };

  // Throws lrsvo::Error unless the vertex is Euclidean, the index in range and
  // lower < upper (both finite). Setting the same parameter again replaces it.
  void set(Vertex* vertex, int index, double lower, double upper);
  // Bounds every parameter of a vertex to value +- tolerance around `centre`.
  void setAround(Vertex* vertex, const double* centre, const double* tolerance);
  const std::vector<Bound>& all() const { return bounds_; }
  bool empty() const { return bounds_.empty(); }

  // The current value of a bounded parameter.
  static double value(const Bound& bound);
  static void setValue(const Bound& bound, double value);
  // True when every bounded parameter lies within [lower, upper].
  bool hold() const;

 private:
  std::vector<Bound> bounds_;
};

}  // namespace lrsvo
