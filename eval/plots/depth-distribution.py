"""Fig. 7: distributions of the triangulated depth, one panel per distance, one curve per camera count."""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
import study_plot  # noqa: E402

folder = study_plot.out_dir()
rows = study_plot.read_csv(folder, "depth_histogram.csv")
stats = study_plot.read_csv(folder, "depth_statistics.csv")
depths = sorted({r["depth_m"] for r in rows})
fig, axes = study_plot.figure(len(depths), width=11.0, height=8.0, rows=2)
for axis, depth, letter in zip(axes, depths, "abcdefgh"):
    for cameras in sorted({r["cameras"] for r in rows}):
        curve = [r for r in rows if r["depth_m"] == depth and r["cameras"] == cameras]
        centres = [0.5 * (r["bin_low_m"] + r["bin_high_m"]) for r in curve]
        axis.plot(centres, [r["density_per_m"] for r in curve], label="%d cameras" % cameras)
    axis.axvline(depth, color="k", linewidth=0.8, linestyle=":")
    axis.set(xlabel="triangulated depth (m)", ylabel="density (1/m)", xlim=(0, 2.5 * depth),
             title="(%s) point at %.0f m" % (letter, depth))
    axis.grid(True, alpha=0.3)
    axis.legend(fontsize=7)
fig.suptitle("0.2 m between cameras, 1 px noise, %d trials per curve" % stats[0]["trials"], fontsize=9)
study_plot.save(fig, folder, "depth-distribution")
