"""Fig. 6: (a) mean range bias against distance for 2, 3 and 4 cameras; (b) disparity between neighbours."""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
import study_plot  # noqa: E402

folder = study_plot.out_dir()
rows = study_plot.read_csv(folder, "range_bias.csv")
focals = sorted({r["focal_px"] for r in rows}, reverse=True)
fig, (bias, disparity) = study_plot.figure(2)
for focal, style in zip(focals, ("-", "--")):
    for colour, cameras in zip(("C0", "C1", "C2", "C3"), sorted({r["cameras"] for r in rows})):
        curve = [r for r in rows if r["focal_px"] == focal and r["cameras"] == cameras]
        depth = [r["depth_m"] for r in curve]
        label = "%d cameras, f %.0f px" % (cameras, focal)
        bias.plot(depth, [r["bias_mean_m"] for r in curve], style, color=colour, marker=".", label=label)
        if cameras == 2:
            disparity.plot(depth, [r["disparity_neighbours_px"] for r in curve], style, color="k",
                           label="neighbours 0.7 m apart, f %.0f px" % focal)
bias.set(xlabel="distance (m)", ylabel="mean depth error (m)",
         title="(a) range bias, 1 px noise, %d trials" % rows[0]["trials"])
disparity.set(xlabel="distance (m)", ylabel="disparity (px)", title="(b) disparity between neighbours")
for axis in (bias, disparity):
    axis.grid(True, alpha=0.3)
    axis.legend(fontsize=7)
study_plot.save(fig, folder, "range-bias")
