// The paper's Fig. 17: the final camera's position error of the long-range
// initialisation (monocular start, then kappa and the bounded extrinsic) and
// of a conventional rigid-stereo start, against flight altitude; extended
// beyond the paper's 100 m to 150 m.

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
#include "lrsvo/frontend/odometry/rigid_stereo_initializer.h"
#include "lrsvo/graph/seed_mix.h"
#include "lrsvo/graph/stopwatch.h"

namespace lrsvo {
namespace {

constexpr int kPaperTrials = 20;
constexpr double kPaperMaxAltitude_m = 100.0;
constexpr double kMaxAltitude_m = 150.0, kAltitudeStep_m = 10.0;
constexpr double kGoalFraction = 0.02;          // "within 2 % of the distance flown"
constexpr double kRigidFailureFraction = 0.10;  // rigid stereo "fails": mean error above 10 % of the distance
// Each initialiser on the flexed rig (the paper's premise) and, as a
// reference, on a rig that kept its calibration exactly.
struct Variant {
  const char* name;
  const char* initializer;
  bool flexed;
};
constexpr Variant kVariants[] = {{"long-range", "long-range", true},
                                 {"rigid-stereo", "rigid-stereo", true},
                                 {"long-range, exact rig", "long-range", false},
                                 {"rigid-stereo, exact rig", "rigid-stereo", false}};

struct Trial {
  double altitude_m;
  std::string method;
  InitializationScore score;
  double scaleStd;  // the initialiser's own relative std of its scale (kappa's marginal)
};

// How far the scale came out, in the initialiser's own standard deviations
// (estimated over true distance, minus one, over kappaRelativeStd), as the
// RMS over the trials that succeeded: about 1 when that std is honest, so
// that the errors are what the flight's information allows.
double scaleErrorInStds(const std::vector<const Trial*>& trials) {
  double sum = 0.0;
  int n = 0;
  for (const Trial* t : trials) {
    if (!t->score.success || !(t->scaleStd > 0.0) || !std::isfinite(t->score.scaleRatio)) continue;
    const double z = (1.0 / t->score.scaleRatio - 1.0) / t->scaleStd;
    sum += z * z;
    ++n;
  }
  return n > 0 ? std::sqrt(sum / n) : std::numeric_limits<double>::quiet_NaN();
}

InitializationResult runMethod(const std::string& method, const SimulatedSequence& sequence, std::uint64_t seed) {
  if (method == "long-range") {
    LongRangeInitializerOptions options;
    options.seed = seed;
    return LongRangeInitializer(options).initialize(sequence.rig, sequence.frames);
  }
  RigidStereoInitializerOptions options;
  options.seed = seed;
  return RigidStereoInitializer(options).initialize(sequence.rig, sequence.frames);
}

struct AltitudeSummary {
  double meanError_m = 0.0, stdError_m = 0.0, medianError_m = 0.0, maxError_m = 0.0, meanPercent = 0.0,
         maxPercent = 0.0;
  int trials = 0, successes = 0, withinFiveMetres = 0;
};

AltitudeSummary summarise(const std::vector<const Trial*>& trials) {
  AltitudeSummary s;
  std::vector<double> errors, percents;
  for (const Trial* t : trials) {
    errors.push_back(t->score.finalPositionError_m);
    percents.push_back(100.0 * t->score.finalPositionError_m / t->score.distanceFlown_m);
    s.successes += t->score.success;
    s.withinFiveMetres += t->score.finalPositionError_m <= 5.0;
  }
  s.trials = static_cast<int>(trials.size());
  const Moments e = sampleMoments(errors);
  s.meanError_m = e.mean;
  s.stdError_m = e.stddev;
  s.maxError_m = *std::max_element(errors.begin(), errors.end());
  s.medianError_m = SortedSample(errors).median();
  s.meanPercent = sampleMoments(percents).mean;
  s.maxPercent = *std::max_element(percents.begin(), percents.end());
  return s;
}

using Case = std::pair<std::string, double>;  // (method, altitude)

std::vector<double> studyAltitudes() {
  std::vector<double> altitudes;
  for (double a = kAltitudeStep_m; a <= kMaxAltitude_m + 1e-9; a += kAltitudeStep_m) altitudes.push_back(a);
  return altitudes;
}

void addSettings(StudyReport& report, const std::vector<double>& altitudes, int trials) {
  using study_support::format;
  const InitializationFlight flight;
  report.addSetting("altitudes_m",
                    format("%g-%g every %g (paper: 10-100)", altitudes.front(), altitudes.back(), kAltitudeStep_m));
  report.addSetting("trials", trials);
  report.addSetting("frames", flight.frames);
  report.addSetting("distance_flown_m", format("%g at most; frames at most %g of the along-track footprint apart",
                                               flight.distance_m, flight.maxFootprintStep));
  report.addSetting("speed_m_s", "15 at 10 m rising linearly to 50 at 100 m, 50 above");
  report.addSetting("rig", "2 cameras, 0.7 m along the fuselage, 1024x768, f = 1280 px (6 mm lens, 1/3\" sensor)");
  report.addSetting("pixel_noise_px", flight.pixelNoise_px);
  report.addSetting("points_per_frame", flight.pointsPerFrame);
  report.addSetting("deformation", format("constant flex uniform within %g of the bounds, vibration 0.05 mm / 0.2 mrad",
                                          flight.flexFraction));
  report.addSetting("long_range",
                    "LongRangeInitializer defaults: 10 frames, kappa, log_barrier, bounds 1 mm / 0.01 rad");
  report.addSetting("rigid_stereo",
                    "RigidStereoInitializer defaults: first-pair triangulation, P3P-MLESAC, BA with S fixed");
}

// Every initialiser on each trial's flight at every altitude, one row per run
// in the trials table.
std::vector<Trial> runTrials(const StudyOptions& options, const std::vector<double>& altitudes, int trials,
                             StudyTable& trialTable) {
  using study_support::format;
  InitializationFlight flight;
  std::vector<Trial> all;
  const int steps = static_cast<int>(altitudes.size()) * trials;
  int step = 0;
  for (double altitude : altitudes) {
    for (int trial = 0; trial < trials; ++trial) {
      flight.altitude_m = altitude;
      flight.speed_m_s = paperSpeedForAltitude(altitude);
      flight.seed = mixSeed(options.seed, static_cast<std::uint64_t>(altitude), static_cast<std::uint64_t>(trial));
      InitializationFlight exact = flight;
      exact.flexFraction = 0.0;
      const SimulatedSequence flexedSequence = simulateSequence(initializationSimulation(flight));
      const SimulatedSequence exactSequence = simulateSequence(initializationSimulation(exact));
      for (const Variant& variant : kVariants) {
        const SimulatedSequence& sequence = variant.flexed ? flexedSequence : exactSequence;
        const InitializationResult result = runMethod(variant.initializer, sequence, flight.seed);
        const InitializationScore score = scoreInitialization(sequence, flight.frames, result);
        all.push_back({altitude, variant.name, score, result.kappaRelativeStd});
        trialTable.addRow(std::vector<std::string>{
            format("%g", altitude), format("%g", flight.speed_m_s), std::to_string(trial), variant.name,
            score.success ? "1" : "0", score.reachedEnd ? "1" : "0", format("%.4f", score.distanceFlown_m),
            format("%.6g", score.finalPositionError_m), format("%.6g", score.rawFinalPositionError_m),
            format("%.6g", 100.0 * score.finalPositionError_m / score.distanceFlown_m),
            format("%.6g", score.scaleRatio), format("%.6g", result.kappaRelativeStd), score.failure});
      }
      ++step;
      options.progress(static_cast<double>(step) / steps, format("%g m, trial %d of %d", altitude, trial + 1, trials));
    }
  }
  return all;
}

struct Summaries {
  std::map<Case, std::vector<const Trial*>> trialsByCase;
  std::map<Case, AltitudeSummary> byCase;
};

Summaries addSummaryTable(StudyReport& report, const std::vector<Trial>& all, const std::vector<double>& altitudes) {
  using study_support::format;
  StudyTable& summaryTable = report.addTable(
      "init_altitude.csv", {"altitude_m", "method", "trials", "successes", "mean_error_m", "std_error_m",
                            "median_error_m", "max_error_m", "mean_error_percent", "max_error_percent", "within_5m"});
  Summaries result;
  auto& trialsByCase = result.trialsByCase;
  auto& summaries = result.byCase;
  for (const Trial& t : all) trialsByCase[{t.method, t.altitude_m}].push_back(&t);
  for (const Variant& variant : kVariants)
    for (double altitude : altitudes) {
      const AltitudeSummary s = summarise(trialsByCase.at({variant.name, altitude}));
      summaries[{variant.name, altitude}] = s;
      summaryTable.addRow(std::vector<std::string>{format("%g", altitude), variant.name, std::to_string(s.trials),
                                                   std::to_string(s.successes), format("%.6g", s.meanError_m),
                                                   format("%.6g", s.stdError_m), format("%.6g", s.medianError_m),
                                                   format("%.6g", s.maxError_m), format("%.6g", s.meanPercent),
                                                   format("%.6g", s.maxPercent), std::to_string(s.withinFiveMetres)});
    }
  return result;
}

void addChecks(StudyReport& report, const Summaries& result, const std::vector<double>& altitudes, int trials) {
  using study_support::format;
  const InitializationFlight flight;
  const auto& trialsByCase = result.trialsByCase;
  const auto& summaries = result.byCase;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const AltitudeSummary& ours100 = summaries.at({"long-range", kPaperMaxAltitude_m});
  const AltitudeSummary& rigid100 = summaries.at({"rigid-stereo", kPaperMaxAltitude_m});
  report.addCheck({"long-range: worst final error at 100 m", ours100.maxError_m, 5.0, "m",
                   "paper: within 5 m in every trial at 100 m"});
  report.addCheck({"long-range: trials within 5 m at 100 m", static_cast<double>(ours100.withinFiveMetres) / trials,
                   1.0, "fraction", ""});
  report.addCheck({"long-range: failed trials at 100 m", static_cast<double>(trials - ours100.successes), 0.0, "trials",
                   "the initialiser's own verdict; each scores the 60 m limit"});
  report.addCheck({"long-range: median final error at 100 m", ours100.medianError_m, nan, "m", ""});
  report.addCheck({"long-range: mean final error at 100 m", ours100.meanPercent, nan, "% of distance",
                   format("distance flown %.0f m", flight.distance_m)});
  report.addCheck({"rigid stereo: mean final error at 100 m", rigid100.meanError_m, 60.0, "m",
                   "paper: consistently fails, error near the 60 m limit of the data set"});

  // The lowest altitude from which the rigid start fails on average, and the
  // first at which ours stops meeting 2 % of the distance flown.
  auto firstAltitude = [&](const std::string& method, auto&& failing) {
    for (double altitude : altitudes)
      if (failing(summaries.at({method, altitude}))) return altitude;
    return nan;
  };
  report.addCheck(
      {"rigid stereo: first altitude with mean error > 10 % of distance",
       firstAltitude("rigid-stereo",
                     [](const AltitudeSummary& s) { return s.meanPercent > 100.0 * kRigidFailureFraction; }),
       40.0, "m", "paper: fails above ~40 m (baseline-to-depth ~0.02)"});
  report.addCheck(
      {"long-range: first altitude with mean error > 2 % of distance",
       firstAltitude("long-range", [](const AltitudeSummary& s) { return s.meanPercent > 100.0 * kGoalFraction; }), nan,
       "m", "beyond the paper (it stops at 100 m); NaN: met up to 150 m"});
  report.addCheck({"long-range, exact rig: first altitude with mean error > 2 % of distance",
                   firstAltitude("long-range, exact rig",
                                 [](const AltitudeSummary& s) { return s.meanPercent > 100.0 * kGoalFraction; }),
                   nan, "m", "reference: the rig kept its calibration; NaN: met up to 150 m"});
  report.addCheck({"rigid stereo, exact rig: mean final error at 100 m",
                   summaries.at({"rigid-stereo, exact rig", kPaperMaxAltitude_m}).meanError_m, nan, "m",
                   "reference: a rigid start is sound when the rig is truly rigid"});
  report.addCheck(
      {"long-range: first altitude with a trial > 2 % of distance",
       firstAltitude("long-range", [](const AltitudeSummary& s) { return s.maxPercent > 100.0 * kGoalFraction; }), nan,
       "m", "beyond the paper; NaN: every trial met it up to 150 m"});
  // Whether the long-range start errs by what its flight's information
  // allows: its scale errors in its own standard deviations, and that std.
  for (double altitude : {kPaperMaxAltitude_m, kMaxAltitude_m}) {
    const std::vector<const Trial*>& trialsThere = trialsByCase.at({"long-range", altitude});
    std::vector<double> stds;
    for (const Trial* t : trialsThere)
      if (std::isfinite(t->scaleStd)) stds.push_back(t->scaleStd);
    report.addCheck({format("long-range: scale error in its own std at %g m (RMS)", altitude),
                     scaleErrorInStds(trialsThere), nan, "std",
                     "about 1: the errors are what the information allows (kappa's marginal std)"});
    report.addCheck({format("long-range: kappa's relative std at %g m (median)", altitude),
                     stds.empty() ? nan : 100.0 * SortedSample(stds).median(), nan, "%",
                     "the scale's std from the information; the final error in % of distance follows it"});
  }
}

StudyReport runInitAltitude(const StudyOptions& options) {
  const Stopwatch stopwatch;
  StudyReport report("init-altitude", "Fig. 17",
                     "Final position error of the long-range and the rigid-stereo initialisation vs altitude");
  const int trials = options.trialsOr(kPaperTrials);
  const std::vector<double> altitudes = studyAltitudes();
  addSettings(report, altitudes, trials);
  StudyTable& trialTable = report.addTable(
      "init_altitude_trials.csv",
      {"altitude_m", "speed_m_s", "trial", "method", "success", "reached_end", "distance_flown_m", "final_error_m",
       "raw_final_error_m", "final_error_percent", "scale_ratio", "scale_std", "failure"});
  const std::vector<Trial> all = runTrials(options, altitudes, trials, trialTable);
  addChecks(report, addSummaryTable(report, all, altitudes), altitudes, trials);
  report.setSeconds(stopwatch.seconds());
  return report;
}

}  // namespace

Study initAltitudeStudy() {
  return Study{"init-altitude", "Fig. 17",
               "Initialisation vs altitude: long-range (kappa) against rigid stereo, 10-150 m", kPaperTrials,
               runInitAltitude};
}

}  // namespace lrsvo
