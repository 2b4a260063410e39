// The paper's Fig. 4: the epipolar error of a deformed, vertically aligned
// stereo pair (0.7 m baseline, a point 100 m along the base camera's optical
// axis) as the secondary camera is translated along, or rotated about, one axis.

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

double epipolarError(double focal_px, const Deformation& deformation) {
  return errorsOf(focal_px, deformation).epipolar_px;
}

StudyReport runEpipolar(const StudyOptions& options) {
  using study_support::format;
  const Stopwatch stopwatch;
  StudyReport report("epipolar", "Fig. 4", "Epipolar error of a deformed, vertically aligned stereo pair");
  const double fOptics = paperOpticsFocal_px(), fImplied = kImpliedFocal_px;
  StudyTable& table = report.addTable(
      "epipolar.csv",
      {"kind", "axis", "amount", "unit", format("epipolar_px_f%.0f", fOptics), format("epipolar_px_f%.0f", fImplied)});
  const std::vector<Deformation> sweep =
      deformationSweep(kMaxTranslation_m, study_support::radians(kMaxRotation_deg), kStepsPerSide);
  for (std::size_t i = 0; i < sweep.size(); ++i) {
    const Deformation& d = sweep[i];
    if (i % (2 * kStepsPerSide + 1) == 0)
      options.progress(static_cast<double>(i) / sweep.size(), describe(d.kind, d.axis));
    const bool translation = d.kind == DeformationKind::kTranslation;
    table.addRow(std::vector<std::string>{
        translation ? "translation" : "rotation", std::string(1, "xyz"[d.axis]),
        format("%.6g", translation ? 1e3 * d.amount : study_support::degrees(d.amount)), translation ? "mm" : "deg",
        format("%.10g", epipolarError(fOptics, d)), format("%.10g", epipolarError(fImplied, d))});
  }
  options.progress(1.0, "done");

  report.addSetting("rig",
                    "vertically aligned pair: secondary centre 0.7 m along the base camera's +y (down the "
                    "image), no rotation; epipolar lines are image columns");
  report.addSetting("axes",
                    "camera frame: x right, y down the image, z optical axis; pitch about x, yaw about y "
                    "(the paper's 'y-axis (yaw)'), roll about z");
  report.addSetting("point", "100 m along the base camera's optical axis");
  report.addSetting("cameras", format("1024 x 768, f %.0f px (6 mm lens, 4.8 mm sensor) and %.0f px (implied by "
                                      "'0.2 deg -> 3 px')",
                                      fOptics, fImplied));
  report.addSetting("sweep",
                    "each axis alone, both signs: translations of the secondary centre up to 100 mm, "
                    "rotations of the secondary camera up to 0.5 deg");
  report.addSetting("epipolar error",
                    "distance of the deformed camera's projection from the calibrated epipolar "
                    "line of the base projection");

  // The most sensitive rotation axis, measured rather than assumed.
  int sensitive = 0;
  double largest = -1.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double e =
        epipolarError(fOptics, {DeformationKind::kRotation, axis, study_support::radians(kCheckRotation_deg)});
    if (e > largest) {
      largest = e;
      sensitive = axis;
    }
  }
  const Deformation rotation{DeformationKind::kRotation, sensitive, study_support::radians(kCheckRotation_deg)};
  const std::string rotationName = describe(rotation.kind, rotation.axis);
  report.addCheck(
      {format("0.2 deg %s, f %.0f px (optics)", rotationName.c_str(), fOptics), epipolarError(fOptics, rotation), 3.0,
       "px", format("the most sensitive of x, y, z; f tan(0.2 deg) = %.2f px", fOptics * std::tan(rotation.amount))});
  report.addCheck({format("0.2 deg %s, f %.0f px (implied)", rotationName.c_str(), fImplied),
                   epipolarError(fImplied, rotation), 3.0, "px", "the f that the paper's 3 px implies"});
  const Deformation alongBaseline{DeformationKind::kTranslation, 1, kCheckTranslation_m};
  report.addCheck({format("50 mm %s (baseline), f %.0f px", describe(alongBaseline.kind, 1).c_str(), fOptics),
                   epipolarError(fOptics, alongBaseline), 1.0, "px",
                   "paper: sub-pixel (< 1 px); a shift along the baseline moves the projection along its epipolar "
                   "line"});
  const Deformation across{DeformationKind::kTranslation, 0, kCheckTranslation_m};
  report.addCheck({format("50 mm %s, f %.0f px", describe(across.kind, 0).c_str(), fOptics),
                   epipolarError(fOptics, across), 1.0, "px",
                   "paper: sub-pixel (< 1 px); across the baseline the shift is f * 50 mm / 100 m"});
  report.setSeconds(stopwatch.seconds());
  return report;
}

}  // namespace

Study epipolarStudy() {
  return Study{"epipolar", "Fig. 4", "Epipolar error of a deformed, vertically aligned stereo pair", 0, runEpipolar};
}

}  // namespace lrsvo
