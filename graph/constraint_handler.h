#pragma once

#include <Eigen/Core>

#include "lrsvo/graph/block_system.h"
#include "lrsvo/graph/graph.h"

namespace lrsvo {

// Hooks through which a constraint method (constraints/: log barrier,
// gradient projection, ...) shapes a solve without the graph, vertices or
// edges knowing. The default handler constrains nothing.
class ConstraintHandler {
 public:
  virtual ~ConstraintHandler() = default;
  // Before the solve: check (or project) the start, add own terms to the graph.
  virtual void begin(Graph&) {}
  // After the solve: remove own terms.
  virtual void end(Graph&) {}
  // After H and g are filled at the current estimates (e.g. hold active bounds).
  virtual void constrainSystem(BlockSystem&) {}
  // Shapes a trial step before it is applied (e.g. project into the box);
  // returns true when it changed the step.
  virtual bool adjustStep(const BlockSystem&, Eigen::VectorXd&) { return false; }
  // After a trial step was applied (e.g. clamp rounding onto the bounds).
  virtual void afterStep(const BlockSystem&) {}
  // Max norm of the (projected) gradient, for the gradient tolerance.
  virtual double gradientMaxNorm(const BlockSystem& system) const {
    return system.gradient().size() ? system.gradient().lpNorm<Eigen::Infinity>() : 0.0;
  }
};

}  // namespace lrsvo
