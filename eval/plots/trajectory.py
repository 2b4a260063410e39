"""`lrsvo eval`: top-down trajectory, position and orientation error over time (from trajectory.csv)."""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
import study_plot  # noqa: E402

folder = study_plot.out_dir()
rows = study_plot.read_csv(folder, "trajectory.csv")
time_key, time_label = ("time_s", "time (s)") if "time_s" in rows[0] else ("frame", "frame")
times = [r[time_key] for r in rows]

# Top-down: the two axes along which the truth spans most (x-y for a z-up world, x-z for KITTI's camera frame).
spans = {axis: max(r["truth_" + axis] for r in rows) - min(r["truth_" + axis] for r in rows) for axis in "xyz"}
first, second = sorted(sorted(spans, key=spans.get, reverse=True)[:2])
fig, (top,) = study_plot.figure(1, width=7.0, height=6.5)
top.plot([r["truth_" + first] for r in rows], [r["truth_" + second] for r in rows], "k-", lw=1.2, label="truth")
top.plot([r["estimate_" + first] for r in rows], [r["estimate_" + second] for r in rows], "r-", lw=1.0,
         label="estimate (SE3-aligned)")
top.plot(rows[0]["truth_" + first], rows[0]["truth_" + second], "ko", label="start")
top.set(xlabel=first + " (m)", ylabel=second + " (m)", aspect="equal", title="trajectory, top-down")
top.grid(True, alpha=0.3)
top.legend(fontsize=8)
study_plot.save(fig, folder, "trajectory_top")

for column, name, label in (("position_error_m", "position_error", "position error (m)"),
                            ("orientation_error_deg", "orientation_error", "orientation error (deg)")):
    fig, (axis,) = study_plot.figure(1, width=8.0, height=3.5)
    axis.plot(times, [r[column] for r in rows], "b-", lw=1.0)
    axis.set(xlabel=time_label, ylabel=label, title=label + " after SE3 alignment")
    axis.grid(True, alpha=0.3)
    study_plot.save(fig, folder, name)
