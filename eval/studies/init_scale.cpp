// The paper's Fig. 18: the long-range initialisation's batch adjustment
// started at a wrong scale, with and without the scale variable kappa, at
// 70 m and 30 m/s. The start scale r is the first monocular pair's distance
// in the map over its true distance; the scale error is the true over the
// estimated distance between the first and the last camera.

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "lrsvo/eval/initialization_trial.h"
#include "lrsvo/eval/sample_statistics.h"
#include "lrsvo/eval/studies/paper_studies.h"
#include "lrsvo/eval/studies/study_support.h"
#include "lrsvo/eval/study.h"
#include "lrsvo/frontend/odometry/long_range_initializer.h"
#include "lrsvo/graph/seed_mix.h"
#include "lrsvo/graph/stopwatch.h"

namespace lrsvo {
namespace {

constexpr int kPaperTrials = 20;
constexpr double kStartScales[] = {0.25, 0.5, 0.75, 0.85, 0.9, 0.95, 1.0, 1.05, 1.1, 1.15, 1.25, 1.5};
// A run has converged when it ends at the scale that the adjustment with
// kappa reaches from the true start scale (the problem's own optimum, which
// is itself some percent off the truth at 70 m: pitch and scale trade off),
// within this relative tolerance.
constexpr double kConvergedTolerance = 0.01;
constexpr double kReferenceStartScale = 1.0;
// "Converges" at a start scale: at least this fraction of the trials do.
constexpr double kReliableFraction = 0.9;

struct Variant {
  const char* name;
  bool estimateScale;
};
constexpr Variant kVariants[] = {{"with-kappa", true}, {"without-kappa", false}};

using Key = std::pair<std::string, double>;  // (variant, start scale)

// What the trials at one (variant, start scale) gave.
struct Tally {
  int converged = 0;
  std::vector<double> after, iterations;
};

struct Tallies {
  std::map<Key, Tally> byKey;
  int invalidTrials = 0;  // trials whose reference run failed: no optimum to converge to
  int trials = 0;
  // At least kReliableFraction of the valid trials converged.
  bool reliable(const char* variant, double startScale) const {
    return byKey.at({variant, startScale}).converged >= kReliableFraction * (trials - invalidTrials);
  }
};

void addSettings(StudyReport& report, const InitializationFlight& flight, int trials) {
  using study_support::format;
  report.addSetting("altitude_m", flight.altitude_m);
  report.addSetting("speed_m_s", flight.speed_m_s);
  report.addSetting("trials", trials);
  report.addSetting("start_scales", "0.25-1.5 (12 values)");
  report.addSetting("frames", flight.frames);
  report.addSetting("distance_flown_m", flight.distance_m);
  report.addSetting("converged", format("recovered scale within %g of the with-kappa result from the true start scale",
                                        kConvergedTolerance));
  report.addSetting("rig", "2 cameras, 0.7 m, 1024x768, f = 1280 px; deformation within the bounds");
}

// Runs every variant from every start scale on each trial's flight, one row
// per run in the trials table.
Tallies runTrials(const StudyOptions& options, InitializationFlight flight, int trials, StudyTable& trialTable) {
  using study_support::format;
  Tallies tallies;
  tallies.trials = trials;
  const int steps = static_cast<int>(std::size(kStartScales)) * trials;
  int step = 0;
  for (int trial = 0; trial < trials; ++trial) {
    flight.seed = mixSeed(options.seed, static_cast<std::uint64_t>(trial));
    const SimulatedSequence sequence = simulateSequence(initializationSimulation(flight));
    const double firstPair_m = (sequence.trueCameraFromWorld[1].inverse().translation() -
                                sequence.trueCameraFromWorld[0].inverse().translation())
                                   .norm();
    std::map<Key, InitializationScore> scores;
    std::map<Key, int> iterations;  // of the batch adjustment
    for (double startScale : kStartScales) {
      for (const Variant& variant : kVariants) {
        LongRangeInitializerOptions initOptions;
        initOptions.estimateScale = variant.estimateScale;
        initOptions.initialBaseline = startScale * firstPair_m;
        initOptions.seed = flight.seed;
        const InitializationResult result = LongRangeInitializer(initOptions).initialize(sequence.rig, sequence.frames);
        scores[{variant.name, startScale}] = scoreInitialization(sequence, flight.frames, result);
        iterations[{variant.name, startScale}] = result.summary.iterationCount();
      }
      ++step;
      options.progress(static_cast<double>(step) / steps,
                       format("trial %d of %d, start scale %g", trial + 1, trials, startScale));
    }
    // A trial whose reference run itself fails (the monocular start broke
    // down) defines no optimum: it is counted apart, not as a convergence.
    const InitializationScore& referenceScore = scores.at({kVariants[0].name, kReferenceStartScale});
    const double reference = referenceScore.scaleRatio;
    if (!referenceScore.success) ++tallies.invalidTrials;
    for (const auto& [key, score] : scores) {
      const bool converged =
          referenceScore.success && std::abs(score.scaleRatio / reference - 1.0) <= kConvergedTolerance;
      Tally& tally = tallies.byKey[key];
      tally.converged += converged;
      if (referenceScore.success) tally.after.push_back(score.scaleRatio);
      tally.iterations.push_back(iterations.at(key));
      trialTable.addRow(std::vector<std::string>{
          format("%g", key.second), key.first, std::to_string(trial), format("%.6g", 1.0 / key.second),
          format("%.6g", score.scaleRatio), format("%.6g", reference), format("%.6g", score.finalPositionError_m),
          std::to_string(iterations.at(key)), converged ? "1" : "0", score.success ? "1" : "0", score.failure});
    }
  }
  return tallies;
}

void addSummaryTable(StudyReport& report, const Tallies& tallies) {
  using study_support::format;
  StudyTable& summaryTable =
      report.addTable("init_scale.csv", {"start_scale", "variant", "scale_error_before", "scale_error_after_mean",
                                         "scale_error_after_std", "converged_fraction", "iterations_mean"});
  for (const Variant& variant : kVariants)
    for (double startScale : kStartScales) {
      const Tally& tally = tallies.byKey.at({variant.name, startScale});
      const Moments m = sampleMoments(tally.after);
      summaryTable.addRow(std::vector<std::string>{
          format("%g", startScale), variant.name, format("%.6g", 1.0 / startScale), format("%.6g", m.mean),
          format("%.6g", m.stddev),
          format("%.4g", static_cast<double>(tally.converged) / std::max(1, tallies.trials - tallies.invalidTrials)),
          format("%.4g", sampleMoments(tally.iterations).mean)});
    }
}

void addChecks(StudyReport& report, const Tallies& tallies) {
  using study_support::format;
  int reliableWithKappa = 0, reliableWithoutKappa = 0;
  for (double startScale : kStartScales) {
    reliableWithKappa += tallies.reliable("with-kappa", startScale);
    reliableWithoutKappa += tallies.reliable("without-kappa", startScale);
  }
  // The widest interval of start scales around 1 over which the run without
  // kappa converges reliably: walk out from the true start scale while it stays reliable.
  const auto* truth = std::find(std::begin(kStartScales), std::end(kStartScales), kReferenceStartScale);
  double lowest = kReferenceStartScale, highest = kReferenceStartScale;
  if (tallies.reliable("without-kappa", *truth)) {
    for (const auto* s = truth; s != std::begin(kStartScales) && tallies.reliable("without-kappa", *(s - 1)); --s)
      lowest = *(s - 1);
    for (const auto* s = truth + 1; s != std::end(kStartScales) && tallies.reliable("without-kappa", *s); ++s)
      highest = *s;
  }
  std::vector<double> errorWithKappa;
  for (double startScale : kStartScales)
    for (double r : tallies.byKey.at({"with-kappa", startScale}).after) errorWithKappa.push_back(std::abs(r - 1.0));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  report.addCheck({"with kappa: start scales that converge reliably",
                   static_cast<double>(reliableWithKappa) / std::size(kStartScales), 1.0, "fraction",
                   "paper: converges at every start scale 0.25-1.5"});
  report.addCheck({"trials whose monocular start failed", static_cast<double>(tallies.invalidTrials), nan, "trials",
                   "left out of the convergence counts: no optimum to converge to"});
  report.addCheck({"with kappa: median |scale error| after",
                   errorWithKappa.empty() ? nan : SortedSample(errorWithKappa).median(), nan, "ratio",
                   "|true / estimated distance - 1|: pitch about y and scale trade off at 70 m"});
  report.addCheck({"without kappa: start scales that converge reliably",
                   static_cast<double>(reliableWithoutKappa) / std::size(kStartScales), 5.0 / 12.0, "fraction",
                   "paper: only within ~10 % of the truth (0.9-1.1: 5 of our 12 start scales hold 0.9 <= r <= 1.1)"});
  for (const Variant& variant : kVariants) {
    std::vector<double> far;
    for (double startScale : {kStartScales[0], kStartScales[std::size(kStartScales) - 1]})
      for (double n : tallies.byKey.at({variant.name, startScale}).iterations) far.push_back(n);
    report.addCheck({format("%s: mean iterations from start scales 0.25 and 1.5", variant.name),
                     sampleMoments(far).mean, nan, "iterations", "of the batch adjustment, every barrier round"});
  }
  report.addCheck({"without kappa: lowest reliable start scale", lowest, 0.9, "ratio",
                   "paper: converges only within ~10 % of the truth"});
  report.addCheck({"without kappa: highest reliable start scale", highest, 1.1, "ratio", ""});
}

StudyReport runInitScale(const StudyOptions& options) {
  const Stopwatch stopwatch;
  StudyReport report("init-scale", "Fig. 18", "Initialisation from a wrong start scale, with and without kappa");
  const int trials = options.trialsOr(kPaperTrials);
  InitializationFlight flight;
  flight.altitude_m = 70.0;
  flight.speed_m_s = 30.0;
  addSettings(report, flight, trials);
  StudyTable& trialTable =
      report.addTable("init_scale_trials.csv",
                      {"start_scale", "variant", "trial", "scale_error_before", "scale_error_after",
                       "scale_error_reference", "final_error_m", "iterations", "converged", "success", "failure"});
  const Tallies tallies = runTrials(options, flight, trials, trialTable);
  addSummaryTable(report, tallies);
  addChecks(report, tallies);
  report.setSeconds(stopwatch.seconds());
  return report;
}

}  // namespace

Study initScaleStudy() {
  return Study{"init-scale", "Fig. 18",
               "Initialisation vs start scale at 70 m: the batch adjustment with and without kappa", kPaperTrials,
               runInitScale};
}

}  // namespace lrsvo
