#include "lrsvo/graph/solver_summary.h"

#include <cstdio>
#include <sstream>

#include <nlohmann/json.hpp>

namespace lrsvo {

const char* terminationName(Termination termination) {
  switch (termination) {
    case Termination::kFunctionTolerance: return "function_tolerance";
    case Termination::kGradientTolerance: return "gradient_tolerance";
    case Termination::kParameterTolerance: return "parameter_tolerance";
    case Termination::kMaxIterations: return "max_iterations";
    case Termination::kTimeLimit: return "time_limit";
    case Termination::kDampingLimit: return "damping_limit";
    case Termination::kNoDescent: return "no_descent";
    case Termination::kSingularSystem: return "singular_system";
    case Termination::kNonFiniteCost: return "non_finite_cost";
  }
  return "unknown";
}

bool isConvergence(Termination termination) {
  return termination == Termination::kFunctionTolerance || termination == Termination::kGradientTolerance ||
         termination == Termination::kParameterTolerance;
}

namespace {
std::string format(const char* pattern, auto... values) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, pattern, values...);
  return buffer;
}
}  // namespace

std::string SolverSummary::briefReport() const {
  return format("%s: cost %.6e -> %.6e, %d iterations (%d accepted), %.3f s, %s", solver.c_str(), initialCost,
                finalCost, iterationCount(), successfulSteps, totalSeconds, terminationName(termination));
}

std::string SolverSummary::fullReport() const {
  std::ostringstream out;
  out << format("Solver %s, %d threads: %d vertices, %d edges, %d parameters\n", solver.c_str(), threads, vertexCount,
                edgeCount, parameterCount);
  out << "iter        cost      cost_change   |gradient|        |step|        lambda  accepted  iter_time  "
         "total_time\n";
  for (const auto& it : iterations)
    out << format("%4d  %.6e  %12.3e  %12.3e  %12.3e  %12.3e  %8s  %8.2e  %10.2e\n", it.iteration, it.cost,
                  it.costChange, it.gradientMaxNorm, it.stepNorm, it.lambda, it.accepted ? "yes" : "no",
                  it.iterationSeconds, it.cumulativeSeconds);
  out << format("Initial cost %.6e, final cost %.6e, change %.6e\n", initialCost, finalCost, initialCost - finalCost);
  out << format("Steps: %d successful, %d unsuccessful\n", successfulSteps, unsuccessfulSteps);
  out << format("Time (s): setup %.4f%s, linearize %.4f, schur %.4f, factorize %.4f, cost %.4f, total %.4f\n",
                setupSeconds, structureReused ? " (structure reused)" : "", linearizeSeconds, schurSeconds,
                factorizeSeconds, costSeconds, totalSeconds);
  if (!ordering.empty())
    out << format("Linear system: %s ordering, %.3e flops per factorisation\n", ordering.c_str(), factorizationFlops);
  out << "Termination: " << terminationName(termination) << (message.empty() ? "" : " (" + message + ")") << '\n';
  return out.str();
}

std::string SolverSummary::toJson() const {
  nlohmann::json json = {
      {"solver", solver},
      {"threads", threads},
      {"vertices", vertexCount},
      {"edges", edgeCount},
      {"parameters", parameterCount},
      {"initial_cost", initialCost},
      {"final_cost", finalCost},
      {"iterations", iterationCount()},
      {"successful_steps", successfulSteps},
      {"unsuccessful_steps", unsuccessfulSteps},
      {"termination", terminationName(termination)},
      {"converged", converged()},
      {"message", message},
      {"total_time_s", totalSeconds},
      {"ordering", ordering},
      {"factorization_flops", factorizationFlops},
      {"structure_reused", structureReused},
      {"phase_time_s",
       {{"setup", setupSeconds},
        {"linearize", linearizeSeconds},
        {"schur", schurSeconds},
        {"factorize", factorizeSeconds},
        {"cost", costSeconds}}},
  };
  nlohmann::json records = nlohmann::json::array();
  for (const auto& it : iterations)
    records.push_back({{"iteration", it.iteration},
                       {"cost", it.cost},
                       {"cost_change", it.costChange},
                       {"gradient_max_norm", it.gradientMaxNorm},
                       {"step_norm", it.stepNorm},
                       {"lambda", it.lambda},
                       {"accepted", it.accepted},
                       {"iteration_time_s", it.iterationSeconds},
                       {"cumulative_time_s", it.cumulativeSeconds}});
  json["iteration_log"] = records;
  return json.dump(2);
}

}  // namespace lrsvo
