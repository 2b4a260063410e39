// The paper's Fig. 1: disparity and depth resolution of a perfect stereo pair
// against depth, for several baselines, at Fig. 1's f = 1200 px and at the
// focal length of the paper's optics (6 mm lens on a 1/3" sensor, 1024 px).

#include <iterator>

#include "lrsvo/eval/depth_resolution.h"
#include "lrsvo/eval/paper_cameras.h"
#include "lrsvo/eval/studies/paper_studies.h"
#include "lrsvo/eval/studies/study_support.h"
#include "lrsvo/eval/study.h"
#include "lrsvo/graph/stopwatch.h"

namespace lrsvo {
namespace {

// The paper's Table 1 (common stereo VO baselines) is lost from the text; these
// span it: a small head (0.1 m), car-mounted rigs (0.25-0.5 m), the paper's 0.7 m, and wider.
constexpr double kBaselines_m[] = {0.1, 0.25, 0.5, 0.7, 1.0, 1.5};
constexpr double kMinDepth_m = 1.0, kMaxDepth_m = 150.0, kDepthStep_m = 0.5;
constexpr double kCheckBaseline_m = 0.7, kCheckDepth_m = 100.0;

StudyReport runDisparity(const StudyOptions& options) {
  using study_support::format;
  const Stopwatch stopwatch;
  StudyReport report("disparity", "Fig. 1", "Disparity and depth resolution of a perfect stereo pair against depth");
  const double fFigure = kFigure1Focal_px, fOptics = paperOpticsFocal_px();
  StudyTable& table =
      report.addTable("disparity.csv", {"focal_px", "baseline_m", "depth_m", "disparity_px", "depth_step_exact_m",
                                        "depth_step_nearer_m", "depth_step_first_order_m"});
  const int depthCount = static_cast<int>((kMaxDepth_m - kMinDepth_m) / kDepthStep_m + 0.5) + 1;
  const int steps = 2 * static_cast<int>(std::size(kBaselines_m));
  int step = 0;
  for (double f : {fFigure, fOptics}) {
    for (double b : kBaselines_m) {
      options.progress(static_cast<double>(step++) / steps, format("f %.0f px, baseline %.2f m", f, b));
      for (int i = 0; i < depthCount; ++i) {
        const double z = kMinDepth_m + i * kDepthStep_m;
        table.addRow({f, b, z, disparity_px(f, b, z), depthStepExact_m(f, b, z), depthStepNearer_m(f, b, z),
                      depthStepFirstOrder_m(f, b, z)});
      }
    }
  }
  options.progress(1.0, "done");

  report.addSetting("focal lengths",
                    format("%.0f px (Fig. 1's normalised f) and %.0f px (6 mm lens, 4.8 mm wide 1/3\" sensor, 1024 px)",
                           fFigure, fOptics));
  report.addSetting("baselines", "0.1, 0.25, 0.5, 0.7, 1.0, 1.5 m (the paper's Table 1 is lost from the text)");
  report.addSetting("depths", format("%.0f to %.0f m every %.1f m", kMinDepth_m, kMaxDepth_m, kDepthStep_m));
  report.addSetting("rig", "perfect: rectified, exact matching, no noise");
  report.addSetting("depth step",
                    "exact: Z(d - 1) - Z(d), the depth one pixel less disparity adds; nearer: Z(d) - Z(d + 1); "
                    "first order: Z^2 / (f b)");

  const double b = kCheckBaseline_m, z = kCheckDepth_m;
  report.addCheck({"disparity, b 0.7 m, Z 100 m, f 1200 px", disparity_px(fFigure, b, z), 8.4, "px",
                   "Fig. 1 (f = 1200 px); the paper quotes 8.4-9 px"});
  report.addCheck({format("disparity, b 0.7 m, Z 100 m, f %.0f px (optics)", fOptics), disparity_px(fOptics, b, z), 9.0,
                   "px", "Section 4.3: ~9 px at 100 m with the flight's cameras"});
  report.addCheck({"depth step, first order Z^2/(f b), f 1200 px", depthStepFirstOrder_m(fFigure, b, z), 12.0, "m",
                   format("Fig. 1 reads ~12 m; the exact one-pixel steps at f 1200 px are %.1f m (d - 1) and %.1f m "
                          "(d + 1)",
                          depthStepExact_m(fFigure, b, z), depthStepNearer_m(fFigure, b, z))});
  report.addCheck({format("depth step, exact Z(d-1) - Z(d), f %.0f px (optics)", fOptics),
                   depthStepExact_m(fOptics, b, z), 12.5, "m",
                   format("Section 4.3: 12.5 m at 100 m with the flight's cameras (first order there: %.1f m)",
                          depthStepFirstOrder_m(fOptics, b, z))});
  report.setSeconds(stopwatch.seconds());
  return report;
}

}  // namespace

Study disparityStudy() {
  return Study{"disparity", "Fig. 1", "Disparity and depth resolution of a perfect stereo pair", 0, runDisparity};
}

}  // namespace lrsvo
