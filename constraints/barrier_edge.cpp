#include "lrsvo/constraints/barrier_edge.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "lrsvo/graph/edge_io.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/registry.h"

namespace lrsvo {

BarrierEdge::BarrierEdge(Vertex* vertex, int index, double lower, double upper, double mu)
    : index_(index), lower_(lower), upper_(upper), mu_(mu) {
  vertices_.assign(1, vertex);
}

double BarrierEdge::value() const {
  std::vector<double> values(vertices_[0]->estimateSize());
  vertices_[0]->getEstimate(values.data());
  return values[index_];
}

double BarrierEdge::cost() const {
  const double x = value();
  if (!(x > lower_ && x < upper_)) return std::numeric_limits<double>::infinity();
  const double y = (x - 0.5 * (lower_ + upper_)) / (0.5 * (upper_ - lower_));
  return -mu_ * std::log1p(-y * y);
}

double BarrierEdge::linearize() {
  const double x = value();
  const double toLower = x - lower_, toUpper = upper_ - x;
  gradient_ = mu_ * (-1.0 / toLower + 1.0 / toUpper);
  hessian_ = mu_ * (1.0 / (toLower * toLower) + 1.0 / (toUpper * toUpper));
  return cost();
}

void BarrierEdge::addHessianBlock(int, int, double* block, int ld) const { block[index_ * ld + index_] += hessian_; }

void BarrierEdge::addGradient(int, double* gradient) const { gradient[index_] += gradient_; }

void BarrierEdge::writeData(std::ostream& out) const {
  out << ' ' << index_;
  writeNumber(out, lower_);
  writeNumber(out, upper_);
  writeNumber(out, mu_);
}

void BarrierEdge::readData(std::istream& in) {
  if (!(in >> index_) || index_ < 0 || index_ >= vertices_[0]->dimension())
    throw Error(std::string(kTypeTag) + ": parameter index missing or out of range");
  lower_ = readNumber(in, kTypeTag);
  upper_ = readNumber(in, kTypeTag);
  mu_ = readNumber(in, kTypeTag);
  if (!(lower_ < upper_) || !(mu_ > 0.0)) throw Error(std::string(kTypeTag) + ": need lower < upper and mu > 0");
  if (!vertices_[0]->isEuclidean()) throw Error(std::string(kTypeTag) + ": the vertex must be Euclidean");
}

}  // namespace lrsvo
