#pragma once

#include <memory>
#include <string>

#include "lrsvo/constraints/bounds.h"
#include "lrsvo/graph/constraint_handler.h"
#include "lrsvo/graph/graph.h"
#include "lrsvo/graph/registry.h"
#include "lrsvo/graph/solver_options.h"
#include "lrsvo/graph/solver_summary.h"

namespace lrsvo {

// What to do when the start lies outside the bounds (or on a bound, for the
// log barrier, which needs a strictly interior start).
enum class StartPolicy {
  kError,    // throw lrsvo::Error naming the vertex and parameter
  kProject,  // move it inside: onto the bound, or a margin inside it for the barrier
};

struct ConstraintSettings {
  StartPolicy start = StartPolicy::kError;
  // Fraction of the half-width kept between a projected start and its bound
  // when the method needs a strictly interior point.
  double interiorMargin = 1e-3;
  // log_barrier: weight mu of -mu log(1 - y^2), y = (x - centre) / half-width,
  // multiplied by barrierDecrease after each of barrierRounds outer solves.
  double barrierMu = 1e-2;
  double barrierDecrease = 0.1;
  int barrierRounds = 3;
  // nlopt_*: evaluations per round; rounds re-anchor the tangent space.
  int nloptMaxEvaluations = 5000;
  int nloptMaxRounds = 20;
};

// A way of keeping a graph's bounded parameters inside their box, chosen by
// name from Registry<ConstraintMethod>: "none", "log_barrier",
// "gradient_projection", "nlopt_lbfgs", "nlopt_mma". Swapping
// the method touches no graph, vertex or edge code.
class ConstraintMethod : public ConstraintHandler {
 public:
  // The constraint library's methods (Registry<ConstraintMethod> adds them on first use).
  static void addBuiltins(Registry<ConstraintMethod>& registry);

  void setBounds(Bounds bounds) { bounds_ = std::move(bounds); }
  const Bounds& bounds() const { return bounds_; }
  void setSettings(const ConstraintSettings& settings) { settings_ = settings; }
  const ConstraintSettings& settings() const { return settings_; }

  // Minimises the graph's cost within the bounds. The summary's initial and
  // final costs are the graph's own (without any barrier terms).
  virtual SolverSummary solve(Graph& graph, const SolverOptions& options);

  void begin(Graph& graph) override;

 protected:
  // Applies the start policy; `interior` asks for a strictly interior start.
  void enforceStart(bool interior) const;
  virtual bool needsInteriorStart() const { return false; }

  Bounds bounds_;
  ConstraintSettings settings_;
};

// Creates the named method with bounds and settings and solves the graph.
SolverSummary optimizeWithBounds(Graph& graph, const SolverOptions& options, const Bounds& bounds,
                                 const std::string& method, const ConstraintSettings& settings = {});

// Appends a later solve's iterations and times to a running summary.
void appendSummary(SolverSummary& total, const SolverSummary& part);

}  // namespace lrsvo
