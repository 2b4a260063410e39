"""Fig. 17: final position error of the initialisation against altitude (m and % of the distance flown),
long-range (kappa) against rigid stereo: mean with one standard deviation, worst trial dotted."""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
import study_plot  # noqa: E402

folder = study_plot.out_dir()
rows = study_plot.read_csv(folder, "init_altitude.csv")
trials = study_plot.read_csv(folder, "init_altitude_trials.csv")
fig, (metres, percent) = study_plot.figure(2)
for method, colour, style in (("long-range", "C0", "-"), ("rigid-stereo", "C3", "--"),
                              ("long-range, exact rig", "C2", "-"), ("rigid-stereo, exact rig", "C1", "--")):
    curve = [r for r in rows if r["method"] == method]
    altitude = [r["altitude_m"] for r in curve]
    for axis, mean, worst, std in ((metres, "mean_error_m", "max_error_m", "std_error_m"),
                                   (percent, "mean_error_percent", "max_error_percent", None)):
        values = [r[mean] for r in curve]
        axis.plot(altitude, values, style, color=colour, marker="o", label=method + " (mean)")
        if std and "exact" not in method:
            spread = [r[std] for r in curve]
            # log axes: the band's lower edge is clipped above zero
            axis.fill_between(altitude, [max(v - s, 0.1 * v) for v, s in zip(values, spread)],
                              [v + s for v, s in zip(values, spread)], color=colour, alpha=0.15)
        if "exact" not in method:
            axis.plot(altitude, [r[worst] for r in curve], ":", color=colour, label=method + " (worst trial)")
    if "exact" in method:
        continue
    points = [t for t in trials if t["method"] == method]
    metres.scatter([t["altitude_m"] for t in points], [t["final_error_m"] for t in points], s=6, color=colour,
                   alpha=0.4)
percent.axhline(2.0, color="k", lw=0.8, ls="-.", label="2 % of distance flown")
metres.axhline(5.0, color="grey", lw=0.8, ls="-.", label="5 m (paper, 100 m)")
metres.axvline(100.0, color="grey", lw=0.5)
percent.axvline(100.0, color="grey", lw=0.5)
metres.set(xlabel="altitude (m)", ylabel="final position error (m)", yscale="log",
           title="(a) error of the last camera, %d trials" % rows[0]["trials"])
percent.set(xlabel="altitude (m)", ylabel="final position error (% of distance flown)", yscale="log",
            title="(b) relative to the distance flown")
for axis in (metres, percent):
    axis.grid(True, alpha=0.3)
    axis.legend(fontsize=7)
study_plot.save(fig, folder, "init-altitude")
