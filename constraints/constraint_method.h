#pragma once

#include <functional>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "lrsvo/constraints/bounds.h"
#include "lrsvo/graph/constraint_handler.h"
#include "lrsvo/graph/graph.h"
#include "lrsvo/graph/optimizer.h"
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

// What every method shares: how a start outside the box is treated. A
// method's own settings (the barrier's mu, NLopt's evaluations, ...) belong to
// the method and are set by name (ConstraintMethod::set, makeConstraintMethod).
struct ConstraintSettings {
  StartPolicy start = StartPolicy::kError;
  // Fraction of the half-width kept between a projected start and its bound
  // when the method needs a strictly interior point.
  double interiorMargin = 1e-3;
};

// One setting a method owns: its name, what it means, and where its value
// lives in the method (a real or an integer).
struct MethodSetting {
  std::string name;
  std::string description;
  std::variant<double*, int*> value;

  std::string valueText() const;
};

// A way of keeping a graph's bounded parameters inside their box, chosen by
// name from Registry<ConstraintMethod>: "none", "log_barrier",
// "gradient_projection", "nlopt_lbfgs", "nlopt_mma". Swapping
// the method touches no graph, vertex or edge code. Each method declares its
// own settings, so a new method with new settings touches no shared struct.
class ConstraintMethod : public ConstraintHandler {
 public:
  ConstraintMethod() = default;
  // The settings point into the object: it is neither copied nor moved.
  ConstraintMethod(const ConstraintMethod&) = delete;
  ConstraintMethod& operator=(const ConstraintMethod&) = delete;

  // The constraint library's methods (Registry<ConstraintMethod> adds them on first use).
  static void addBuiltins(Registry<ConstraintMethod>& registry);

  void setBounds(Bounds bounds) { bounds_ = std::move(bounds); }
  const Bounds& bounds() const { return bounds_; }
  void setSettings(const ConstraintSettings& settings) { settings_ = settings; }
  const ConstraintSettings& settings() const { return settings_; }

  // Sets one of the method's own settings from text, e.g. ("mu", "0.01").
  // Throws lrsvo::Error on an unknown name (listing the method's settings) or
  // a value that is not a finite number of the setting's kind.
  void set(const std::string& name, const std::string& value);
  // The method's own settings with their current values, in declaration order.
  const std::vector<MethodSetting>& ownSettings() const { return ownSettings_; }

  // Minimises the graph's cost within the bounds. The summary's initial and
  // final costs are the graph's own (without any barrier terms).
  virtual SolverSummary solve(Graph& graph, const SolverOptions& options);

  void begin(Graph& graph) override;

 protected:
  // Applies the start policy; `interior` asks for a strictly interior start.
  void enforceStart(bool interior) const;
  virtual bool needsInteriorStart() const { return false; }
  // Sets the step of every bounded parameter the solve holds to
  // limit(bound, value, step); true when any step changed.
  using StepLimit = std::function<double(const Bounds::Bound&, double value, double step)>;
  bool limitBoundedSteps(const BlockSystem& system, Eigen::VectorXd& dx, const StepLimit& limit) const;
  // Declares a setting of the method's own (in its constructor): its name,
  // the member holding its value (which is also the default), its meaning.
  void declare(std::string name, double* value, std::string description);
  void declare(std::string name, int* value, std::string description);

  Bounds bounds_;
  ConstraintSettings settings_;

 private:
  std::vector<MethodSetting> ownSettings_;
};

// Creates a method from its specification "name[:setting=value,...]", e.g.
// "log_barrier:mu=0.01,rounds=3"; the settings not named keep the method's
// defaults. Throws lrsvo::Error on an unknown method or setting, or a bad value.
std::unique_ptr<ConstraintMethod> makeConstraintMethod(const std::string& specification);
// The method's name in a specification (the text before ':').
std::string constraintMethodName(const std::string& specification);

// Creates the method of a specification (makeConstraintMethod) with bounds and
// settings and solves the graph.
SolverSummary optimizeWithBounds(Graph& graph, const SolverOptions& options, const Bounds& bounds,
                                 const std::string& specification, const ConstraintSettings& settings = {});

// Appends a later solve's iterations and times to a running summary.
void appendSummary(SolverSummary& total, const SolverSummary& part);

}  // namespace lrsvo
