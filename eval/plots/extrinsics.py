"""The stereo extrinsic's six parameters over a run, estimated (and true when
known) against the box they are bounded to (the paper's Figs. 24-25).

usage: extrinsics.py EXTRINSICS_CSV RIG_JSON OUT_PNG
"""
import csv
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

LABELS = ["x (mm)", "y (mm)", "z (mm)", "roll (mrad)", "pitch (mrad)", "yaw (mrad)"]
KEYS = ["x_m", "y_m", "z_m", "roll_rad", "pitch_rad", "yaw_rad"]


def main(csv_path, rig_path, png_path):
    rig = json.load(open(rig_path))
    rows = list(csv.DictReader(open(csv_path)))
    figure, axes = plt.subplots(3, 2, figsize=(11, 8), sharex=True)
    for camera in rig["secondary"]:
        k = camera["camera"]
        mine = [r for r in rows if int(r["camera"]) == k]
        times = [float(r["time_s"]) for r in mine]
        for i, key in enumerate(KEYS):
            axis = axes[i % 3][i // 3]
            centre = camera["calibration"][i]
            half = rig["tolerance"][i]
            # Departure from calibration, in mm or mrad.
            estimate = [1e3 * (float(r[key]) - centre) for r in mine]
            axis.plot(times, estimate, lw=1, label=f"estimated (camera {k})")
            truth = [(t, 1e3 * (float(r["true_" + key]) - centre)) for t, r in zip(times, mine) if r["true_" + key]]
            if truth:
                axis.plot([t for t, _ in truth], [v for _, v in truth], lw=1, ls="--", label=f"true (camera {k})")
            for bound in (-half, half):
                axis.axhline(1e3 * bound, color="red", lw=0.8)
            axis.set_ylabel(LABELS[i])
    for axis in axes[-1]:
        axis.set_xlabel("time (s)")
    axes[0][0].legend(fontsize=8)
    figure.suptitle("Stereo extrinsic: change from calibration, bounds in red")
    figure.tight_layout()
    figure.savefig(png_path, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
