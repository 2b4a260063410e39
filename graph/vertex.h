#pragma once

#include <memory>

#include <Eigen/Core>

namespace lrsvo {

// A parameter block of the graph: a point on a manifold with a tangent-space
// update (oplus). Fixed vertices are held constant; marginalised vertices are
// eliminated by the Schur complement (as points are in bundle adjustment).
class Vertex {
 public:
  explicit Vertex(int id = -1) : id_(id) {}
  virtual ~Vertex() = default;

  int id() const { return id_; }
  void setId(int id) { id_ = id; }

  bool fixed() const { return fixed_; }
  void setFixed(bool fixed) { fixed_ = fixed; }
  bool marginalized() const { return marginalized_; }
  void setMarginalized(bool marginalized) { marginalized_ = marginalized; }

  // Size of the update (tangent space).
  virtual int dimension() const = 0;
  // Number of stored parameters, as read and written by getEstimate/setEstimate.
  virtual int estimateSize() const = 0;
  virtual void getEstimate(double* values) const = 0;
  // Throws lrsvo::Error when the values do not describe a valid state.
  virtual void setEstimate(const double* values) = 0;
  // x <- x [+] delta, delta of size dimension().
  virtual void oplus(const double* delta) = 0;
  // True when oplus adds delta element-wise to the estimate: then parameter i
  // is coordinate i of the update, which bounds on parameters need.
  virtual bool isEuclidean() const { return false; }
  // Tag naming the type in graph files; the type registers under it.
  virtual const char* typeTag() const = 0;
  virtual std::unique_ptr<Vertex> clone() const = 0;

 private:
  int id_;
  bool fixed_ = false;
  bool marginalized_ = false;
};

// Vertex with a compile-time dimension D, so edges can use fixed-size Jacobians.
template <int D>
class BaseVertex : public Vertex {
 public:
  static constexpr int kDimension = D;
  using Vertex::Vertex;
  int dimension() const final { return D; }
};

// A vertex living in R^D: the estimate is the vector and oplus is addition.
template <int D>
class VectorVertex : public BaseVertex<D> {
 public:
  using Estimate = Eigen::Matrix<double, D, 1>;
  using BaseVertex<D>::BaseVertex;

  const Estimate& estimate() const { return estimate_; }
  void setEstimateVector(const Estimate& estimate) {
    estimate_ = estimate;
    estimateChanged();
  }

  int estimateSize() const final { return D; }
  void getEstimate(double* values) const final { Eigen::Map<Estimate>{values} = estimate_; }
  void setEstimate(const double* values) final { setEstimateVector(Eigen::Map<const Estimate>(values)); }
  void oplus(const double* delta) final { setEstimateVector(estimate_ + Eigen::Map<const Estimate>(delta)); }
  bool isEuclidean() const final { return true; }

  // What automatically differentiated edges read (graph/autodiff_edge.h): the
  // state at the estimate, and the state after oplus(delta) with delta of any
  // scalar type (dual numbers carry the derivatives through the update).
  const Estimate& state() const { return estimate_; }
  template <typename T>
  Eigen::Matrix<T, D, 1> perturbed(const Eigen::Matrix<T, D, 1>& delta) const {
    return delta + estimate_;  // mixed: a dual plus a double costs no derivative work
  }

 protected:
  // Called after every change of the estimate: a derived vertex refreshes
  // what it caches from it (e.g. a rotation matrix the edges read).
  virtual void estimateChanged() {}

  Estimate estimate_ = Estimate::Zero();
};

}  // namespace lrsvo
