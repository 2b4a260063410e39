#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "lrsvo/constraints/constraint_method.h"
#include "lrsvo/graph/base_cost_edge.h"
#include "lrsvo/graph/block_system.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/registry.h"
#include "lrsvo/sim/window_problem.h"

// The constraint plugins on seeded stereo windows: the box holds,
// KKT holds at the solution, inactive bounds change nothing, and with active
// bounds the log barrier, gradient projection and NLopt agree.
//
// Windows fix their first two poses. With one fixed pose the map's scale is
// a gauge freedom shared with the extrinsic's centre c (scaling the map and c
// together leaves every projection unchanged), so the optimum along c_x is not
// unique and different methods legitimately stop at different points of that
// valley; two fixed poses (in a sliding window, poses carried over from the
// previous window) make the optimum unique and the methods comparable.
//
// NLopt's methods are first order and need hundreds (L-BFGS) to tens of
// thousands (MMA: 35 000 evaluations, ~3 s) of graph evaluations, so they
// run on a small window (3 frames, 20 points) instead of the VO's (15 frames,
// 500 points: MMA took over 2 minutes on an 8-frame, 120-point window).

namespace lrsvo {
namespace {

using Vector6 = VertexStereoExtrinsic::Vector6;

bool isNlopt(const std::string& method) { return method.rfind("nlopt_", 0) == 0; }

// Every registered method that keeps bounds (all but "none").
std::vector<std::string> boundedMethods() {
  std::vector<std::string> names;
  for (const auto& [name, entry] : Registry<ConstraintMethod>::instance().entries())
    if (name != "none") names.push_back(name);
  return names;
}

// Tight stopping rules, so that KKT and agreement checks see converged solutions.
SolverOptions tightOptions() {
  SolverOptions options;
  options.linearSolver = "schur_dense";
  options.maxIterations = 200;
  options.functionTolerance = 1e-12;
  options.parameterTolerance = 1e-14;
  return options;
}

// The calibration start is inside every box, so kProject changes no start of
// ours; it keeps the log barrier's later rounds from tripping over their own
// near-bound start (see LogBarrierRoundsContinueFromAnIterateNearAnActiveBound).
ConstraintSettings projectingSettings() {
  ConstraintSettings settings;
  settings.start = StartPolicy::kProject;
  return settings;
}

enum class Box {
  kActive,  // the true roll and yaw 1.5 tolerances from the calibration: outside the box
  kWide,    // +-1 m, +-0.5 rad around the default (small) deformation: never reached
};

enum class Size { kVo, kSmall };

Size sizeFor(const std::string& method) { return isNlopt(method) ? Size::kSmall : Size::kVo; }

WindowProblemOptions windowFor(Size size, Box box) {
  WindowProblemOptions options;
  options.fixedPoses = 2;
  if (size == Size::kSmall) {
    options.frames = 3;
    options.points = 20;
    options.minTrackLength = options.maxTrackLength = 3;
  }
  if (box == Box::kActive) options.trueOutsideBounds = true;
  if (box == Box::kWide) {
    options.positionTolerance_m = 1.0;
    options.angleTolerance_rad = 0.5;
  }
  return options;
}

// A zero cost term on the extrinsic that records, whenever the optimiser
// linearises (at every accepted iterate, and at every NLopt evaluation),
// whether the extrinsic is inside its box.
struct BoxRecord {
  const Bounds* bounds = nullptr;
  int visits = 0;
  int outside = 0;
};

class BoxWatcher : public BaseCostEdge<VertexStereoExtrinsic> {
 public:
  static constexpr const char* kTypeTag = "TEST_BOX_WATCHER";
  explicit BoxWatcher(BoxRecord* record) : record_(record) {}
  const char* typeTag() const override { return kTypeTag; }
  double cost() const override { return 0.0; }
  void computeGradientHessian(Gradient& gradient, Hessian& hessian) const override {
    gradient.setZero();
    hessian.setZero();
    ++record_->visits;
    if (!record_->bounds->hold()) ++record_->outside;
  }
  void writeData(std::ostream&) const override {}
  void readData(std::istream&) override { throw Error("BoxWatcher is not read from files"); }

 private:
  BoxRecord* record_;
};

void copyEstimates(const Graph& from, Graph& to) {
  std::vector<double> values;
  for (const auto& vertex : from.vertices()) {
    values.resize(vertex->estimateSize());
    vertex->getEstimate(values.data());
    to.vertex(vertex->id())->setEstimate(values.data());
  }
}

struct Solved {
  WindowProblem problem;
  SolverSummary summary;
  BoxRecord box;
};

// Solves the window from `start` (every vertex estimate copied) or from its own start.
std::unique_ptr<Solved> solve(const WindowProblemOptions& window, const std::string& method,
                              const WindowProblem* start = nullptr) {
  auto solved = std::make_unique<Solved>(Solved{makeWindowProblem(window), {}, {}});
  WindowProblem& problem = solved->problem;
  if (start) copyEstimates(start->graph, problem.graph);
  solved->box.bounds = &problem.extrinsicBounds;
  auto watcher = std::make_unique<BoxWatcher>(&solved->box);
  watcher->setVertex(0, problem.extrinsic);
  problem.graph.addEdge(std::move(watcher));
  solved->summary =
      optimizeWithBounds(problem.graph, tightOptions(), problem.extrinsicBounds, method, projectingSettings());
  const Vector6 d = problem.extrinsic->estimate() - problem.calibratedExtrinsic;
  std::printf(
      "  %-19s %3d frames: cost %.4e -> %.10e, %3d iterations, %6.3f s, s - calibration "
      "(%+.3e %+.3e %+.3e m, %+.6f %+.6f %+.6f rad)\n",
      method.c_str(), static_cast<int>(problem.poses.size()), solved->summary.initialCost, solved->summary.finalCost,
      solved->summary.iterationCount(), solved->summary.totalSeconds, d[0], d[1], d[2], d[3], d[4], d[5]);
  return solved;
}

// Each (method, box, size) is solved once per test run and shared by the tests.
const Solved& solution(const std::string& method, Box box, Size size) {
  static std::map<std::tuple<std::string, Box, Size>, std::unique_ptr<Solved>> cache;
  auto& slot = cache[{method, box, size}];
  if (!slot) slot = solve(windowFor(size, box), method);
  return *slot;
}
const Solved& solution(const std::string& method, Box box) { return solution(method, box, sizeFor(method)); }

// KKT of min E(x) over the box, with the graph's own gradient g and
// Gauss-Newton diagonal h (a fresh BlockSystem, barrier terms gone): every
// coordinate off the bounds has |g| / sqrt(h) small (the cost decrease one
// coordinate could still give is about that squared over 2); a coordinate on
// a bound may have a large gradient, but only pointing out of the box
// (g >= 0 at a lower bound, g <= 0 at an upper one, so -g leaves the box).
struct Kkt {
  double worstFree = 0.0;        // max |g| / sqrt(h) off the bounds
  double worstInward = 0.0;      // max inward-pointing -g / sqrt(h) at a bound
  double weakestActive = 1e300;  // min outward g / sqrt(h) at a bound
  int activeBounds = 0;
};

// `onBound`: distance from a bound, as a fraction of the half-width, within
// which a parameter counts as on it.
Kkt measureKkt(const WindowProblem& problem, double onBound) {
  BlockSystem system(problem.graph, false);
  system.fill(1);
  const Eigen::VectorXd& g = system.gradient();
  const Eigen::VectorXd& h = system.diagonal();
  const int extrinsicBlock = system.blockOf(problem.extrinsic);
  Kkt kkt;
  for (int b = 0; b < system.blockCount(); ++b)
    for (int c = 0; c < system.dim(b); ++c) {
      const int k = system.offset(b) + c;
      const double scaled = g[k] / std::sqrt(std::max(h[k], 1e-300));
      if (b == extrinsicBlock) {
        const Bounds::Bound& bound = problem.extrinsicBounds.all()[c];
        const double x = Bounds::value(bound);
        const double outward = x <= bound.lower + onBound * bound.halfWidth()   ? scaled
                               : x >= bound.upper - onBound * bound.halfWidth() ? -scaled
                                                                                : std::nan("");
        if (!std::isnan(outward)) {
          ++kkt.activeBounds;
          kkt.worstInward = std::max(kkt.worstInward, -outward);
          kkt.weakestActive = std::min(kkt.weakestActive, outward);
          continue;
        }
      }
      kkt.worstFree = std::max(kkt.worstFree, std::abs(scaled));
    }
  std::printf("  KKT: max |g|/sqrt(h) off the bounds %.2e; %d on a bound, min outward %.2e, max inward %.2e\n",
              kkt.worstFree, kkt.activeBounds, kkt.weakestActive, kkt.worstInward);
  return kkt;
}

// Largest distance of a bounded parameter outside its box, in half-widths (0 inside).
double worstViolation(const WindowProblem& problem) {
  double worst = 0.0;
  for (const Bounds::Bound& bound : problem.extrinsicBounds.all()) {
    const double x = Bounds::value(bound);
    worst = std::max(worst, std::max(bound.lower - x, x - bound.upper) / bound.halfWidth());
  }
  return worst;
}

TEST(Constraints, UnconstrainedOptimumOfTheActiveWindowsLiesOutsideTheBox) {
  for (const Size size : {Size::kVo, Size::kSmall}) {
    const Solved& solved = solution("none", Box::kActive, size);
    const auto& bounds = solved.problem.extrinsicBounds.all();
    EXPECT_GT(Bounds::value(bounds[3]), bounds[3].upper + 0.3 * bounds[3].halfWidth()) << "roll";
    EXPECT_LT(Bounds::value(bounds[5]), bounds[5].lower - 0.3 * bounds[5].halfWidth()) << "yaw";
    EXPECT_GT(solved.box.outside, 0);
  }
}

TEST(Constraints, EveryPluginKeepsTheExtrinsicInItsBox) {
  for (const std::string& method : boundedMethods()) {
    const Solved& solved = solution(method, Box::kActive);
    EXPECT_TRUE(solved.problem.extrinsicBounds.hold()) << method;
    EXPECT_EQ(worstViolation(solved.problem), 0.0) << method;
    EXPECT_GT(solved.box.visits, 0) << method;
    EXPECT_EQ(solved.box.outside, 0) << method << ": an accepted iterate or an evaluation left the box";
    EXPECT_LT(solved.summary.finalCost, 0.1 * solved.summary.initialCost) << method;
  }
}

// Gradient projection and NLopt end exactly on their active bounds.
TEST(Constraints, KktHoldsAtTheSolution) {
  for (const std::string& method : boundedMethods()) {
    if (method == "log_barrier") continue;  // interior: see the next test
    SCOPED_TRACE(method);
    const Kkt kkt = measureKkt(solution(method, Box::kActive).problem, 1e-9);
    EXPECT_GE(kkt.activeBounds, 2) << "roll and yaw at least";
    EXPECT_EQ(kkt.worstInward, 0.0);
    // 1e-3: no coordinate alone could lower the cost by more than ~5e-7.
    EXPECT_LT(kkt.worstFree, method == "gradient_projection" ? 1e-5 : 1e-3);
  }
}

// With mu = 1e-4 after its rounds, the barrier stops just inside the bounds
// that the unconstrained optimum lies beyond (roll, yaw), where the barrier's
// gradient mu / distance balances the cost's.
TEST(Constraints, LogBarrierEndsJustInsideTheActiveBounds) {
  const WindowProblem& problem = solution("log_barrier", Box::kActive).problem;
  const auto& bounds = problem.extrinsicBounds.all();
  const double rollGap = (bounds[3].upper - Bounds::value(bounds[3])) / bounds[3].halfWidth();
  const double yawGap = (Bounds::value(bounds[5]) - bounds[5].lower) / bounds[5].halfWidth();
  std::printf("  distance to the bound in half-widths: roll %.2e, yaw %.2e\n", rollGap, yawGap);
  EXPECT_GT(rollGap, 0.0);
  EXPECT_GT(yawGap, 0.0);
  EXPECT_LT(rollGap, 1e-6);
  EXPECT_LT(yawGap, 1e-6);
  // Every other coordinate is at a stationary point of the cost, or held by
  // the barrier within 5 % of a bound with the cost's gradient pointing out.
  const Kkt kkt = measureKkt(problem, 0.05);
  EXPECT_EQ(kkt.worstInward, 0.0);
  EXPECT_LT(kkt.worstFree, 1e-4);
}

// Stated tolerance: cost within 1e-6 (relative), angles within 1e-5 rad,
// the centre c within 0.5 mm. c is barely observable from 100 m (the
// unconstrained c moves 5-30 cm from the calibration here), so first-order
// methods stop at slightly different points of its flat valley (L-BFGS:
// 0.14 mm and 1.3e-6 rad from "none", at a cost 8e-8 above it).
//
// MMA from the common start needs ~90 000 evaluations (8 s) to come within
// 1e-7 of the cost along that valley, too slow for a unit test: it starts at
// the unconstrained optimum instead and must stay there, which still shows
// that inactive bounds do not move a solution.
TEST(Constraints, InactiveBoundsGiveTheUnconstrainedSolution) {
  for (const std::string& method : boundedMethods()) {
    SCOPED_TRACE(method);
    const Solved& free = solution("none", Box::kWide, sizeFor(method));
    std::unique_ptr<Solved> warm;
    if (method == "nlopt_mma") warm = solve(windowFor(sizeFor(method), Box::kWide), method, &free.problem);
    const Solved& bounded = warm ? *warm : solution(method, Box::kWide);
    const Vector6 difference = bounded.problem.extrinsic->estimate() - free.problem.extrinsic->estimate();
    std::printf("  %-19s vs none: cost %+.2e relative, |dc| %.2e m, |dangles| %.2e rad\n", method.c_str(),
                bounded.summary.finalCost / free.summary.finalCost - 1.0, difference.head<3>().norm(),
                difference.tail<3>().norm());
    EXPECT_EQ(measureKkt(bounded.problem, 1e-9).activeBounds, 0);
    EXPECT_NEAR(bounded.summary.finalCost, free.summary.finalCost, 1e-6 * free.summary.finalCost);
    EXPECT_LT(difference.head<3>().norm(), 5e-4);
    EXPECT_LT(difference.tail<3>().norm(), 1e-5);
  }
}

// On the VO window the barrier against gradient projection; on the small
// window every method against gradient projection. Stated tolerance: cost
// within 1e-6 (relative), c within 0.01 mm, angles within 1e-6 rad.
TEST(Constraints, ActiveBoundsAgreeAcrossBarrierGradientProjectionAndNlopt) {
  const std::string reference = "gradient_projection";
  for (const Size size : {Size::kVo, Size::kSmall}) {
    const Solved& gp = solution(reference, Box::kActive, size);
    for (const std::string& method : boundedMethods()) {
      if (method == reference || (size == Size::kVo && isNlopt(method))) continue;
      SCOPED_TRACE(method);
      const Solved& other = solution(method, Box::kActive, size);
      const Vector6 difference = other.problem.extrinsic->estimate() - gp.problem.extrinsic->estimate();
      std::printf("  %-19s vs %s: cost %+.2e relative, |dc| %.2e m, |dangles| %.2e rad\n", method.c_str(),
                  reference.c_str(), other.summary.finalCost / gp.summary.finalCost - 1.0, difference.head<3>().norm(),
                  difference.tail<3>().norm());
      EXPECT_NEAR(other.summary.finalCost, gp.summary.finalCost, 1e-6 * gp.summary.finalCost);
      EXPECT_LT(difference.head<3>().norm(), 1e-5);  // 1 % of the position tolerance
      EXPECT_LT(difference.tail<3>().norm(), 1e-6);  // 0.01 % of the angle tolerance
    }
  }
}

TEST(Constraints, StartOutsideTheBoxIsAnErrorOrProjected) {
  WindowProblemOptions window = windowFor(Size::kSmall, Box::kActive);
  SolverOptions noIterations = tightOptions();
  noIterations.maxIterations = 0;  // LM stops at the (projected) start
  const ConstraintSettings project = projectingSettings();
  // NLopt ignores maxIterations: a short run, as only the box matters here.
  const auto specification = [](const std::string& method) {
    return method.rfind("nlopt_", 0) == 0 ? method + ":evaluations=50,rounds=1" : method;
  };
  for (const std::string& method : boundedMethods()) {
    SCOPED_TRACE(method);
    WindowProblem problem = makeWindowProblem(window);
    const Bounds::Bound roll = problem.extrinsicBounds.all()[3];
    Bounds::setValue(roll, roll.upper + 0.5 * roll.halfWidth());
    try {
      optimizeWithBounds(problem.graph, tightOptions(), problem.extrinsicBounds, method);
      ADD_FAILURE() << "no error for a start outside the box";
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find("outside the bounds"), std::string::npos) << error.what();
    }
    optimizeWithBounds(problem.graph, noIterations, problem.extrinsicBounds, specification(method), project);
    EXPECT_TRUE(problem.extrinsicBounds.hold());
    if (method == "gradient_projection") {
      EXPECT_EQ(Bounds::value(roll), roll.upper) << "projected onto the bound";
    }
    if (method == "log_barrier") {
      const double margin = ConstraintSettings().interiorMargin * roll.halfWidth();
      EXPECT_DOUBLE_EQ(Bounds::value(roll), roll.upper - margin) << "projected strictly inside";
    }
  }
  // "none" ignores the bounds, so any start is fine.
  WindowProblem problem = makeWindowProblem(window);
  Bounds::setValue(problem.extrinsicBounds.all()[3], 1.0);
  EXPECT_NO_THROW(optimizeWithBounds(problem.graph, noIterations, problem.extrinsicBounds, "none"));
}

TEST(Constraints, BoundsOnAPoseAreRejected) {
  WindowProblem problem = makeWindowProblem(windowFor(Size::kSmall, Box::kActive));
  Bounds bounds;
  EXPECT_THROW(bounds.set(problem.poses[2], 0, -1.0, 1.0), Error);
  EXPECT_NO_THROW(bounds.set(problem.points[0], 2, -1000.0, 1000.0));
}

// The costs an iteration record carries never rise; accepted steps lower it.
::testing::AssertionResult costsNeverRise(const SolverSummary& summary) {
  int accepted = 0;
  for (std::size_t k = 1; k < summary.iterations.size(); ++k) {
    const IterationRecord& record = summary.iterations[k];
    if (record.cost > summary.iterations[k - 1].cost)
      return ::testing::AssertionFailure() << "iteration " << record.iteration << ": cost " << record.cost << " after "
                                           << summary.iterations[k - 1].cost;
    if (record.accepted && !(record.costChange > 0.0))
      return ::testing::AssertionFailure()
             << "iteration " << record.iteration << " accepted a cost change of " << record.costChange;
    accepted += record.accepted;
  }
  std::printf("  %d iterations, %d accepted\n", summary.iterationCount(), accepted);
  return ::testing::AssertionSuccess();
}

// LM under the barrier accepts only steps that lower F = E + barrier, and
// never spends an iteration on a point outside the box: a step that would
// take a parameter out of it, or onto its bound, goes a fraction of the way
// there instead, so every trial F is finite. One round at a fixed small mu,
// on a window whose unconstrained roll and yaw lie outside the box: both end
// pressed against their bounds, within the barrier's reach of them.
TEST(Constraints, LogBarrierNeverAcceptsACostIncreaseNorTriesAPointOutsideTheBox) {
  WindowProblem problem = makeWindowProblem(windowFor(Size::kSmall, Box::kActive));
  const SolverSummary summary =
      optimizeWithBounds(problem.graph, tightOptions(), problem.extrinsicBounds, "log_barrier:mu=1e-4,rounds=1");
  EXPECT_TRUE(summary.converged()) << summary.fullReport();
  EXPECT_TRUE(costsNeverRise(summary));
  for (const IterationRecord& record : summary.iterations)
    EXPECT_TRUE(std::isfinite(record.costChange))
        << "iteration " << record.iteration << " tried a point outside the box";
  EXPECT_TRUE(problem.extrinsicBounds.hold());
  const auto& bounds = problem.extrinsicBounds.all();
  EXPECT_GT(Bounds::value(bounds[3]), bounds[3].upper - 0.01 * bounds[3].halfWidth()) << "roll";
  EXPECT_LT(Bounds::value(bounds[5]), bounds[5].lower + 0.01 * bounds[5].halfWidth()) << "yaw";
}

// boundary_fraction is a fraction of the way to a bound: 0 would never move
// a bounded parameter, more than 1 would step past the bound.
TEST(Constraints, LogBarrierBoundaryFractionLiesInZeroToOne) {
  for (const char* fraction : {"0", "1.5", "-0.5"}) {
    WindowProblem problem = makeWindowProblem(windowFor(Size::kSmall, Box::kActive));
    EXPECT_THROW(optimizeWithBounds(problem.graph, tightOptions(), problem.extrinsicBounds,
                                    std::string("log_barrier:boundary_fraction=") + fraction),
                 Error)
        << fraction;
  }
}

// boundary_fraction = 1 is the plain barrier: a step is tried whole, so on
// the window whose roll and yaw press against their bounds some trial steps
// leave the box, cost +inf and are rejected. It still never accepts a cost
// increase and ends inside the box.
TEST(Constraints, LogBarrierWithWholeStepsRejectsThoseThatLeaveTheBox) {
  WindowProblem problem = makeWindowProblem(windowFor(Size::kSmall, Box::kActive));
  const SolverSummary summary = optimizeWithBounds(problem.graph, tightOptions(), problem.extrinsicBounds,
                                                   "log_barrier:mu=1e-4,rounds=1,boundary_fraction=1");
  EXPECT_TRUE(costsNeverRise(summary));
  const auto outside = std::count_if(summary.iterations.begin(), summary.iterations.end(),
                                     [](const IterationRecord& r) { return !std::isfinite(r.costChange); });
  EXPECT_GT(outside, 0);
  EXPECT_TRUE(problem.extrinsicBounds.hold());
}

// The barrier's later rounds start where the previous round stopped: strictly
// inside the box but, at an active bound, far closer to it than the interior
// margin asked of a user's start, so the default start policy (kError) must
// not reject it (nor kProject move it). Across rounds F still never rises:
// the barrier term is >= 0 and mu only shrinks, so the next round's F is
// lower at the same point.
TEST(Constraints, LogBarrierRoundsContinueFromAnIterateNearAnActiveBound) {
  WindowProblem problem = makeWindowProblem(windowFor(Size::kSmall, Box::kActive));
  ASSERT_TRUE(problem.extrinsicBounds.hold());
  SolverSummary summary;
  EXPECT_NO_THROW(summary = optimizeWithBounds(problem.graph, tightOptions(), problem.extrinsicBounds, "log_barrier"));
  EXPECT_TRUE(problem.extrinsicBounds.hold());
  EXPECT_TRUE(costsNeverRise(summary));
  EXPECT_TRUE(costsNeverRise(solution("log_barrier", Box::kActive).summary)) << "kProject, VO window";
}

// The rounds keep one set of barrier edges in the graph (only mu changes
// between them, so every round solves the structure the first one set up);
// the solve takes them out again and reports the graph's own costs.
TEST(Constraints, LogBarrierRoundsLeaveTheGraphAsItWas) {
  WindowProblem problem = makeWindowProblem(windowFor(Size::kSmall, Box::kActive));
  std::vector<const Edge*> before;
  for (const auto& edge : problem.graph.edges()) before.push_back(edge.get());
  const double initialCost = problem.graph.cost();
  const SolverSummary summary =
      optimizeWithBounds(problem.graph, tightOptions(), problem.extrinsicBounds, "log_barrier:rounds=3");
  std::vector<const Edge*> after;
  for (const auto& edge : problem.graph.edges()) after.push_back(edge.get());
  EXPECT_EQ(after, before);
  EXPECT_EQ(summary.initialCost, initialCost);
  EXPECT_EQ(summary.finalCost, problem.graph.cost());
  EXPECT_TRUE(problem.extrinsicBounds.hold());
}

}  // namespace
}  // namespace lrsvo

namespace lrsvo {
namespace {

std::string errorOf(const std::string& specification) {
  try {
    (void)makeConstraintMethod(specification);
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

std::map<std::string, std::string> settingsOf(const ConstraintMethod& method) {
  std::map<std::string, std::string> values;
  for (const MethodSetting& setting : method.ownSettings()) values[setting.name] = setting.valueText();
  return values;
}

TEST(ConstraintSpecification, NamesAMethodAndAnyOfItsOwnSettings) {
  EXPECT_EQ(settingsOf(*makeConstraintMethod("log_barrier")),
            (std::map<std::string, std::string>{
                {"boundary_fraction", "0.995"}, {"decrease", "0.1"}, {"mu", "0.01"}, {"rounds", "3"}}));
  EXPECT_EQ(settingsOf(*makeConstraintMethod("log_barrier:mu=1e-4,rounds=1,boundary_fraction=0.9")),
            (std::map<std::string, std::string>{
                {"boundary_fraction", "0.9"}, {"decrease", "0.1"}, {"mu", "1e-04"}, {"rounds", "1"}}));
  EXPECT_EQ(settingsOf(*makeConstraintMethod("nlopt_mma:evaluations=50")),
            (std::map<std::string, std::string>{{"evaluations", "50"}, {"rounds", "20"}}));
  EXPECT_TRUE(makeConstraintMethod("gradient_projection")->ownSettings().empty());
  EXPECT_EQ(constraintMethodName("log_barrier:rounds=1"), "log_barrier");
}

TEST(ConstraintSpecification, ErrorsNameTheSpecificationAndTheMethodsSettings) {
  const std::string unknownSetting = errorOf("log_barrier:mu=0.1,rnds=2");
  for (const char* part : {"log_barrier:mu=0.1,rnds=2", "'rnds'", "mu", "decrease", "rounds"})
    EXPECT_NE(unknownSetting.find(part), std::string::npos) << unknownSetting;
  EXPECT_NE(errorOf("log_barrier:rounds=2.5").find("integer"), std::string::npos);
  EXPECT_NE(errorOf("log_barrier:mu=nan").find("finite number"), std::string::npos);
  EXPECT_NE(errorOf("log_barrier:mu=").find("finite number"), std::string::npos);
  EXPECT_NE(errorOf("log_barrier:mu").find("setting=value"), std::string::npos);
  EXPECT_NE(errorOf("log_barrier:").find("setting=value"), std::string::npos);
  EXPECT_NE(errorOf("none:rounds=1").find("no settings"), std::string::npos);
  const std::string unknownMethod = errorOf("log_barier:mu=1");
  EXPECT_NE(unknownMethod.find("log_barier"), std::string::npos) << unknownMethod;
  EXPECT_NE(unknownMethod.find("gradient_projection"), std::string::npos) << "the known methods";
}

// The barrier's minimiser lies where the cost's gradient g balances the
// barrier's, about mu / gap near a bound: the gap grows with mu, so six orders
// of magnitude of mu must show in the gap of an active bound.
TEST(ConstraintSpecification, TheBarriersSettingsReachItsSolve) {
  double gap[2] = {0.0, 0.0};
  const char* specifications[2] = {"log_barrier:mu=1,rounds=1", "log_barrier:mu=1e-6,rounds=1"};
  for (int k = 0; k < 2; ++k) {
    WindowProblem problem = makeWindowProblem(windowFor(Size::kSmall, Box::kActive));
    optimizeWithBounds(problem.graph, tightOptions(), problem.extrinsicBounds, specifications[k]);
    const Bounds::Bound roll = problem.extrinsicBounds.all()[3];
    gap[k] = (roll.upper - Bounds::value(roll)) / roll.halfWidth();
  }
  std::printf("  roll's gap to its bound in half-widths: mu 1: %.3e, mu 1e-6: %.3e\n", gap[0], gap[1]);
  EXPECT_GT(gap[1], 0.0);
  EXPECT_GT(gap[0], 10.0 * gap[1]);
}

}  // namespace
}  // namespace lrsvo
