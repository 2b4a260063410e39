"""Fig. 4: epipolar error against a translation (left) and a rotation (right) of the secondary camera."""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
import study_plot  # noqa: E402

folder = study_plot.out_dir()
rows = study_plot.read_csv(folder, "epipolar.csv")
errors = study_plot.columns_like(rows, "epipolar_px_f")
fig, axes = study_plot.figure(2)
names = {"translation": {"x": "x", "y": "y (baseline)", "z": "z (optical axis)"},
         "rotation": {"x": "x (pitch)", "y": "y (yaw)", "z": "z (roll)"}}
for axis, kind in zip(axes, ("translation", "rotation")):
    for column, style in zip(errors, ("-", "--")):
        focal = column.split("_f")[-1]
        for colour, name in zip(("C0", "C1", "C2"), ("x", "y", "z")):
            curve = [r for r in rows if r["kind"] == kind and r["axis"] == name]
            axis.plot([r["amount"] for r in curve], [r[column] for r in curve], style, color=colour,
                      label="%s, f %s px" % (names[kind][name], focal))
    unit = curve[0]["unit"]
    axis.set(xlabel="%s of the secondary camera (%s)" % (kind, unit), ylabel="epipolar error (px)",
             title="%s: b = 0.7 m, point at 100 m" % kind)
    axis.grid(True, alpha=0.3)
    axis.legend(fontsize=7)
study_plot.save(fig, folder, "epipolar")
