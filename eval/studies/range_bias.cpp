// The paper's Fig. 6: the range bias of least-squares triangulation from 2, 3
// and 4 cameras in a line, 0.7 m apart, with 1 px Gaussian pixel noise, for a
// point 20-120 m away; and the disparity between neighbouring cameras.

#include <cmath>
#include <iterator>
#include <map>

#include "lrsvo/eval/depth_resolution.h"
#include "lrsvo/eval/line_rig.h"
#include "lrsvo/eval/paper_cameras.h"
#include "lrsvo/eval/sample_statistics.h"
#include "lrsvo/eval/studies/paper_studies.h"
#include "lrsvo/eval/studies/study_support.h"
#include "lrsvo/eval/study.h"
#include "lrsvo/eval/triangulation_trials.h"
#include "lrsvo/graph/stopwatch.h"

namespace lrsvo {
namespace {

constexpr int kPaperTrials = 100000;
constexpr int kCameraCounts[] = {2, 3, 4};
constexpr double kSpacing_m = 0.7, kNoise_px = 1.0;
constexpr double kMinDepth_m = 20.0, kMaxDepth_m = 120.0, kDepthStep_m = 5.0;

// The second-order bias of 1 / w for a fitted inverse depth w ~ N(1/Z, s^2):
// E[1/w] - Z ~ Z^3 s^2, with s = noise / (f sqrt(sum (x_k - mean x)^2)).
double secondOrderBias_m(const LineRig& rig, double depth_m) {
  double mean = 0.0, spread = 0.0;
  for (double x : rig.centres_m) mean += x / rig.cameraCount();
  for (double x : rig.centres_m) spread += (x - mean) * (x - mean);
  const double s = kNoise_px / (rig.intrinsics.fx * std::sqrt(spread));
  return depth_m * depth_m * depth_m * s * s;
}

struct CaseResult {
  double bias_m = 0.0;
  long failed = 0;
};

StudyReport runRangeBias(const StudyOptions& options) {
  using study_support::format;
  const Stopwatch stopwatch;
  StudyReport report("range-bias", "Fig. 6", "Range bias of triangulation from 2, 3 and 4 cameras in a line");
  const long trials = options.trialsOr(kPaperTrials);
  const double focalLengths_px[] = {paperOpticsFocal_px(), kImpliedFocal_px};
  StudyTable& table =
      report.addTable("range_bias.csv", {"focal_px", "cameras", "depth_m", "trials", "failed", "bias_mean_m",
                                         "depth_error_median_m", "error_mean_m", "error_median_m",
                                         "bias_second_order_m", "disparity_neighbours_px", "disparity_span_px"});
  const int depthCount = static_cast<int>((kMaxDepth_m - kMinDepth_m) / kDepthStep_m + 0.5) + 1;
  const int steps = static_cast<int>(std::size(focalLengths_px) * std::size(kCameraCounts)) * depthCount;
  std::map<std::pair<int, int>, CaseResult> atFarthest;  // (focal index, cameras) at the largest depth
  long failedInAll = 0;
  int step = 0;
  for (std::size_t fi = 0; fi < std::size(focalLengths_px); ++fi) {
    const double f = focalLengths_px[fi];
    for (int cameras : kCameraCounts) {
      const LineRig rig = LineRig::evenlySpaced(paperIntrinsics(f), cameras, kSpacing_m);
      for (int i = 0; i < depthCount; ++i) {
        const double depth = kMinDepth_m + i * kDepthStep_m;
        options.progress(static_cast<double>(step) / steps, format("%d cameras, %.0f m, f %.0f px", cameras, depth, f));
        const TriangulationTrials run =
            runTriangulationTrials(rig, Eigen::Vector3d(0.0, 0.0, depth), kNoise_px, trials, options.seed, step++);
        std::vector<double> depthErrors(run.depths_m.size());
        for (std::size_t t = 0; t < depthErrors.size(); ++t) depthErrors[t] = run.depths_m[t] - depth;
        const double bias = sampleMoments(depthErrors).mean;
        const bool any = !depthErrors.empty();
        const double nan = std::nan("");
        const double disparity = disparity_px(f, kSpacing_m, depth);
        table.addRow({f, static_cast<double>(cameras), depth, static_cast<double>(run.count()),
                      static_cast<double>(run.failed), bias, any ? SortedSample(depthErrors).median() : nan,
                      sampleMoments(run.errors_m).mean, any ? SortedSample(run.errors_m).median() : nan,
                      secondOrderBias_m(rig, depth), disparity, (cameras - 1) * disparity});
        failedInAll += run.failed;
        if (i == depthCount - 1) atFarthest[{static_cast<int>(fi), cameras}] = {bias, run.failed};
      }
    }
  }

  report.addSetting("cameras", format("2, 3 and 4 in a horizontal line, %.1f m between neighbours, parallel optical "
                                      "axes, 1024 x 768",
                                      kSpacing_m));
  report.addSetting("focal lengths", format("%.0f px (6 mm lens, 4.8 mm wide 1/3\" sensor) and %.0f px (implied by "
                                            "Section 2's '0.2 deg -> 3 px')",
                                            focalLengths_px[0], focalLengths_px[1]));
  report.addSetting("points", format("%.0f to %.0f m every %.0f m, on the optical axis through the rig's centre",
                                     kMinDepth_m, kMaxDepth_m, kDepthStep_m));
  report.addSetting("noise", "1 px Gaussian on both image axes of every camera, independent");
  report.addSetting("trials per depth", static_cast<double>(trials));
  report.addSetting("triangulation",
                    "least squares over all cameras (maximum likelihood), in closed form for this "
                    "rectified geometry; equal to frontend's triangulate (unit test)");
  report.addSetting("bias", "mean of (triangulated depth - true depth) over the trials that gave a point");
  report.addSetting("failed trials",
                    format("%ld in all: fitted disparity <= 0, no point in front (column 'failed')", failedInAll));

  const double farthest = kMaxDepth_m;
  for (std::size_t fi = 0; fi < std::size(focalLengths_px); ++fi) {
    const double f = focalLengths_px[fi];
    const LineRig pair = LineRig::evenlySpaced(paperIntrinsics(f), 2, kSpacing_m);
    const CaseResult two = atFarthest.at({static_cast<int>(fi), 2}), four = atFarthest.at({static_cast<int>(fi), 4});
    report.addCheck({format("pair at 120 m, f %.0f px", f), two.bias_m, 3.0, "m",
                     format("paper: nearly 3 m; second-order theory Z^3 2 sigma^2 / (f b)^2 = %.2f m; %ld failed",
                            secondOrderBias_m(pair, farthest), two.failed)});
    report.addCheck({format("four cameras at 120 m, f %.0f px", f), four.bias_m, 0.5, "m",
                     format("paper: < 0.5 m; %ld failed", four.failed)});
  }
  // Another reading of "1 px Gaussian noise": 1 px on the disparity, i.e. 1 / sqrt(2) px on each image.
  const double f = focalLengths_px[0];
  const TriangulationTrials disparityNoise = runTriangulationTrials(
      LineRig::evenlySpaced(paperIntrinsics(f), 2, kSpacing_m), Eigen::Vector3d(0.0, 0.0, farthest),
      kNoise_px / std::sqrt(2.0), trials, options.seed, step);
  report.addCheck(
      {format("pair at 120 m, f %.0f px, 1 px noise on the disparity", f),
       sampleMoments(disparityNoise.depths_m).mean - farthest, 3.0, "m",
       format("another reading of the paper's noise: 0.71 px per image; %ld failed", disparityNoise.failed)});
  options.progress(1.0, "done");
  report.setSeconds(stopwatch.seconds());
  return report;
}

}  // namespace

Study rangeBiasStudy() {
  return Study{"range-bias", "Fig. 6", "Range bias of triangulation from 2, 3 and 4 cameras in a line", kPaperTrials,
               runRangeBias};
}

}  // namespace lrsvo
