"""Fig. 18: scale error (true over estimated distance) before and after the batch adjustment against the
start scale, with and without kappa; every trial as a dot, the mean as a line."""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
import study_plot  # noqa: E402

folder = study_plot.out_dir()
rows = study_plot.read_csv(folder, "init_scale.csv")
trials = study_plot.read_csv(folder, "init_scale_trials.csv")
fig, (axis,) = study_plot.figure(1, width=7.0, height=4.6)
before = [r for r in rows if r["variant"] == "with-kappa"]
axis.plot([r["start_scale"] for r in before], [r["scale_error_before"] for r in before], "k:", marker="x",
          label="before adjustment")
for variant, colour in (("with-kappa", "C0"), ("without-kappa", "C3")):
    curve = [r for r in rows if r["variant"] == variant]
    axis.plot([r["start_scale"] for r in curve], [r["scale_error_after_mean"] for r in curve], "-", color=colour,
              marker="o", label="after, " + variant.replace("-", " ") + " (mean)")
    points = [t for t in trials if t["variant"] == variant]
    axis.scatter([t["start_scale"] for t in points], [t["scale_error_after"] for t in points], s=8, color=colour,
                 alpha=0.35)
axis.axhline(1.0, color="C2", lw=0.8, label="truth")
axis.set(xlabel="start scale (map over true distance of the first pair)",
         ylabel="scale error (true over estimated distance)", yscale="log",
         title="Initialisation at 70 m from a wrong scale")
axis.grid(True, alpha=0.3)
axis.legend(fontsize=7)
study_plot.save(fig, folder, "init-scale")
