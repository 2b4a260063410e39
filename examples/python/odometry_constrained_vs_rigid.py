#!/usr/bin/env python3
"""The odometry on the built-in rendered flight, constrained (S bounded) and rigid, against the truth.

    PYTHONPATH=build/python python3 examples/python/odometry_constrained_vs_rigid.py --frames 300 --out vo.png

Prints each variant's ATE and KITTI drift and draws both tracks over the truth, seen from above, and
their position errors over time (each aligned to the truth by the rotation and translation the ATE uses).
"""

import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import lrsvo


def truth_at(truth, times):
    """The true positions at the estimate's times (the truth holds every frame run)."""
    rows = np.searchsorted(truth[:, 0], times)
    return truth[np.clip(rows, 0, len(truth) - 1), 1:4]


def align_se3(estimate, truth):
    """The estimate's positions moved by the rotation and translation that best fit the truth (Horn / Umeyama)."""
    mean_e, mean_t = estimate.mean(axis=0), truth.mean(axis=0)
    u, _, vt = np.linalg.svd((truth - mean_t).T @ (estimate - mean_e))
    d = np.diag([1.0, 1.0, np.sign(np.linalg.det(u @ vt))])
    rotation = u @ d @ vt
    return (estimate - mean_e) @ rotation.T + mean_t


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--source", default="sim:demo", help="any source `lrsvo run` takes (default sim:demo)")
    parser.add_argument("--frames", type=int, default=300, help="frames to run (default 300: 10 s of the flight)")
    parser.add_argument("--out", default="constrained_vs_rigid.png", help="the plot (PNG)")
    args = parser.parse_args()

    runs = {
        "constrained (S bounded)": lrsvo.run(args.source, frames=args.frames, plot=False),
        "rigid stereo": lrsvo.run(args.source, frames=args.frames, plot=False, rigid=True),
    }
    truth = next(iter(runs.values())).truth
    figure, (track, error) = plt.subplots(1, 2, figsize=(12, 5))
    track.plot(truth[:, 1], truth[:, 2], "k-", linewidth=2, label="truth")
    for name, result in runs.items():
        m = result.metrics
        print(f"{name:24s} ATE {m.get('ate_rmse_m', float('nan')):8.3f} m   drift {m.get('drift_percent') or float('nan'):7.3f} %"
              f"   {m['frames_tracked']} of {m['frames']} frames tracked")
        times = result.trajectory[:, 0]
        true_positions = truth_at(truth, times)
        aligned = align_se3(result.trajectory[:, 1:4], true_positions)
        track.plot(aligned[:, 0], aligned[:, 1], label=name)
        error.semilogy(times - times[0], np.linalg.norm(aligned - true_positions, axis=1), label=name)
    track.set_xlabel("x (m)")
    track.set_ylabel("y (m)")
    track.set_aspect("equal", adjustable="datalim")
    track.set_title(f"{args.source}, {args.frames} frames, from above")
    track.legend()
    error.set_xlabel("time (s)")
    error.set_ylabel("position error after alignment (m)")
    error.grid(True, which="both", alpha=0.3)
    error.legend()
    figure.savefig(args.out, dpi=120, bbox_inches="tight")
    print("wrote", args.out)


if __name__ == "__main__":
    main()
