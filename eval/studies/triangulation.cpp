// The paper's Fig. 5: the triangulation error of a deformed, vertically
// aligned stereo pair: the point 100 m along the base camera's optical axis is
// triangulated from its projections with the calibrated (undeformed) extrinsic.

#include <cmath>

#include "lrsvo/eval/paper_cameras.h"
#include "lrsvo/eval/studies/paper_studies.h"
#include "lrsvo/eval/studies/section2_setup.h"
#include "lrsvo/eval/studies/study_support.h"
#include "lrsvo/eval/study.h"
#include "lrsvo/graph/stopwatch.h"

namespace lrsvo {
namespace {

using namespace section2;

std::string number(double value) { return std::isfinite(value) ? study_support::format("%.10g", value) : ""; }

StudyReport runTriangulation(const StudyOptions& options) {
  using study_support::format;
  const Stopwatch stopwatch;
  StudyReport report("triangulation", "Fig. 5", "Triangulation error of a deformed, vertically aligned stereo pair");
  const double fOptics = paperOpticsFocal_px(), fImplied = kImpliedFocal_px;
  StudyTable& table =
      report.addTable("triangulation.csv", {"kind", "axis", "amount", "unit", format("error_m_f%.0f", fOptics),
                                            format("error_m_f%.0f", fImplied), format("depth_m_f%.0f", fOptics)});
  const std::vector<Deformation> sweep =
      deformationSweep(kMaxTranslation_m, study_support::radians(kMaxRotation_deg), kStepsPerSide);
  int failed = 0;
  for (std::size_t i = 0; i < sweep.size(); ++i) {
    const Deformation& d = sweep[i];
    if (i % (2 * kStepsPerSide + 1) == 0)
      options.progress(static_cast<double>(i) / sweep.size(), describe(d.kind, d.axis));
    const bool translation = d.kind == DeformationKind::kTranslation;
    const DeformedPairErrors optics = errorsOf(fOptics, d), implied = errorsOf(fImplied, d);
    if (!std::isfinite(optics.triangulation_m)) ++failed;
    table.addRow(std::vector<std::string>{
        translation ? "translation" : "rotation", std::string(1, "xyz"[d.axis]),
        format("%.6g", translation ? 1e3 * d.amount : study_support::degrees(d.amount)), translation ? "mm" : "deg",
        number(optics.triangulation_m), number(implied.triangulation_m), number(optics.triangulatedDepth_m)});
  }
  options.progress(1.0, "done");

  report.addSetting("rig",
                    "vertically aligned pair: secondary centre 0.7 m along the base camera's +y (down the "
                    "image), no rotation");
  report.addSetting("axes",
                    "camera frame: x right, y down the image, z optical axis; pitch about x, yaw about y "
                    "(the paper's 'y-axis (yaw)'), roll about z");
  report.addSetting("point", "100 m along the base camera's optical axis");
  report.addSetting("cameras",
                    format("1024 x 768, f %.0f px (6 mm lens, 4.8 mm sensor) and %.0f px", fOptics, fImplied));
  report.addSetting("triangulation",
                    "least squares over both projections (frontend's triangulate: DLT, then "
                    "Gauss-Newton) with the calibrated extrinsic; no pixel noise");
  report.addSetting("sweep", "each axis alone, both signs: translations up to 100 mm, rotations up to 0.5 deg");
  report.addSetting("failed", format("%d of %zu deformations leave no point in front of both cameras (negative "
                                     "disparity): empty cells in the CSV",
                                     failed, sweep.size()));

  const double angle = study_support::radians(kCheckRotation_deg);
  for (double sign : {1.0, -1.0}) {
    const DeformedPairErrors e = errorsOf(fOptics, {DeformationKind::kRotation, 0, sign * angle});
    report.addCheck({format("%+.1f deg rotation about x (pitch)", sign * kCheckRotation_deg), e.triangulation_m, 30.0,
                     "m",
                     format("paper: > 30 m 'about y'; about x the projection moves along the epipolar column and "
                            "the disparity changes: depth %.1f m",
                            e.triangulatedDepth_m)});
  }
  const DeformedPairErrors yaw = errorsOf(fOptics, {DeformationKind::kRotation, 1, angle});
  report.addCheck({"+0.2 deg rotation about y (yaw)", yaw.triangulation_m, 30.0, "m",
                   format("the paper's axis; it moves the projection across the epipolar line (Fig. 4's error), "
                          "which least squares spreads sideways (about Z * angle / 2 = %.2f m), not in depth",
                          0.5 * kDepth_m * angle)});
  const DeformedPairErrors along = errorsOf(fOptics, {DeformationKind::kTranslation, 1, kCheckTranslation_m});
  report.addCheck({"+50 mm translation along y (baseline)", along.triangulation_m, std::nan(""), "m",
                   "no number in the paper; the baseline changes by 50 / 700"});
  const DeformedPairErrors implied = errorsOf(fImplied, {DeformationKind::kRotation, 0, angle});
  report.addCheck({format("+0.2 deg about x, f %.0f px", fImplied), implied.triangulation_m, 30.0, "m",
                   format("without noise the error does not depend on f (f %.0f px above)", fOptics)});
  report.setSeconds(stopwatch.seconds());
  return report;
}

}  // namespace

Study triangulationStudy() {
  return Study{"triangulation", "Fig. 5", "Triangulation error of a deformed, vertically aligned stereo pair", 0,
               runTriangulation};
}

}  // namespace lrsvo
