#pragma once

#include <iosfwd>
#include <vector>

#include "lrsvo/graph/vertex.h"

namespace lrsvo {

// A term of the objective joining any number of vertices. The optimiser only
// sees this interface: after linearize() an edge hands out its gradient and
// Gauss-Newton (or exact) Hessian blocks per vertex, so least-squares edges and
// cost edges (barriers, priors with their own Hessian) enter the same system.
class Edge {
 public:
  virtual ~Edge() = default;

  virtual int vertexCount() const = 0;
  // The length of the residual a least-squares edge whitens: its information
  // matrix is that square. 0 for a cost edge, which has none.
  virtual int residualDimension() const { return 0; }
  Vertex* vertex(int k) const { return vertices_[k]; }
  const std::vector<Vertex*>& vertices() const { return vertices_; }
  void setVertex(int k, Vertex* vertex) { vertices_.at(k) = vertex; }

  // Tag naming the type in graph files; the type registers under it.
  virtual const char* typeTag() const = 0;
  // Whether slot k may hold this vertex (its type is the one the edge reads).
  // Graph::addEdge refuses an edge whose vertices it does not accept.
  virtual bool acceptsVertex(int k, const Vertex& vertex) const = 0;

  // The edge's term of the objective at the current estimates, Ceres'
  // convention 1/2 rho(||r||^2) for least squares; +inf when infeasible.
  virtual double cost() const = 0;
  // Evaluates and caches what the blocks need; returns cost().
  virtual double linearize() = 0;
  // After linearize(): block += d2F / (d vertex a, d vertex b), a dim(a) x dim(b)
  // column-major block with leading dimension ld.
  virtual void addHessianBlock(int a, int b, double* block, int ld) const = 0;
  // After linearize(): gradient += dF / d vertex a.
  virtual void addGradient(int a, double* gradient) const = 0;
  // Geodesic acceleration (docs/autodiff.md): after linearize() at x, with
  // every active vertex moved on to x [+] h v, adds J_k^T r'' to gradients[k]
  // for each vertex k, where r'' = (2/h) ((r(x [+] h v) - r(x)) / h - J v) is
  // the second derivative of the residual along v, whitened and weighted as in
  // the blocks. steps[k] is vertex k's part of v; both pointers are null for a
  // vertex without a block. A cost edge adds nothing: its curvature is in H.
  virtual void addSecondDirectionalGradient(double h, const double* const* steps, double* const* gradients) const {
    (void)h, (void)steps, (void)gradients;
  }
  // Type-specific data in graph files (measurement, information, kernel, ...).
  virtual void writeData(std::ostream& out) const = 0;
  // Throws lrsvo::Error on missing or invalid values.
  virtual void readData(std::istream& in) = 0;

 protected:
  std::vector<Vertex*> vertices_;
};

}  // namespace lrsvo
