"""Fig. 5: triangulation error against a translation (left) and a rotation (right) of the secondary camera."""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
import study_plot  # noqa: E402

folder = study_plot.out_dir()
rows = study_plot.read_csv(folder, "triangulation.csv")
column = study_plot.columns_like(rows, "error_m_f")[0]  # without noise every f gives the same error
fig, axes = study_plot.figure(2)
names = {"translation": {"x": "x", "y": "y (baseline)", "z": "z (optical axis)"},
         "rotation": {"x": "x (pitch)", "y": "y (yaw)", "z": "z (roll)"}}
for axis, kind in zip(axes, ("translation", "rotation")):
    for colour, name in zip(("C0", "C1", "C2"), ("x", "y", "z")):
        curve = [r for r in rows if r["kind"] == kind and r["axis"] == name]
        axis.plot([r["amount"] for r in curve], [r[column] for r in curve], color=colour, label=names[kind][name])
    axis.set(xlabel="%s of the secondary camera (%s)" % (kind, curve[0]["unit"]),
             ylabel="distance from the true point (m)", yscale="log", ylim=(1e-3, None),
             title="%s: b = 0.7 m, point at 100 m" % kind)
    axis.grid(True, which="both", alpha=0.3)
    axis.legend(fontsize=8)
axes[1].text(0.02, 0.02, "gaps: negative disparity, no point in front", transform=axes[1].transAxes, fontsize=7)
study_plot.save(fig, folder, "triangulation")
