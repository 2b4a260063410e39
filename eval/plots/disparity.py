"""Fig. 1: disparity and depth resolution against depth, one curve per baseline (f = 1200 px)."""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
import study_plot  # noqa: E402

folder = study_plot.out_dir()
rows = study_plot.read_csv(folder, "disparity.csv")
focal = min(r["focal_px"] for r in rows)  # Fig. 1's f = 1200 px
rows = [r for r in rows if r["focal_px"] == focal]
fig, (steps, disparities) = study_plot.figure(2)
for baseline in sorted({r["baseline_m"] for r in rows}):
    curve = [r for r in rows if r["baseline_m"] == baseline]
    depth = [r["depth_m"] for r in curve]
    label = "b = %g m" % baseline
    steps.plot(depth, [r["depth_step_exact_m"] for r in curve], label=label)
    disparities.plot(depth, [r["disparity_px"] for r in curve], label=label)
steps.set(xlabel="depth Z (m)", ylabel="depth step Z(d - 1) - Z(d) (m)", ylim=(0, 40),
          title="depth resolution, f = %.0f px" % focal)
disparities.set(xlabel="depth Z (m)", ylabel="disparity f b / Z (px)", yscale="log",
                title="disparity, f = %.0f px" % focal)
for axis in (steps, disparities):
    axis.grid(True, alpha=0.3)
    axis.legend(fontsize=8)
study_plot.save(fig, folder, "disparity")
