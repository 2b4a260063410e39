#!/usr/bin/env python3
"""Runs `lrsvo run` on each stress condition and prints one Markdown table row per
condition and build: ATE in % of the distance flown, path length over the true one,
frames posed (measured; predicted ones in brackets), segments, frames whose tracks the
whole image's shift predicted, frames posed against a lost segment's map, the
odometry's fps, and the mean time per frame of detection and of the window adjustment
(`metrics.json`'s `ms_per_frame`): where a change's time goes, stage by stage.

Give one `--lrsvo` per build to compare; the builds take turns on each condition, so
a drift in the machine's speed falls on both alike. `--variants` adds, for the last
build, the unconstrained (S free) and the rigid (S at its calibration) odometry beside
the constrained one. Run from the repository's top:

    scripts/robustness_table.py --lrsvo build/bin/lrsvo --out robustness
    scripts/robustness_table.py --lrsvo OLD/bin/lrsvo --lrsvo build/bin/lrsvo --only gust,stress
    scripts/robustness_table.py --lrsvo build/bin/lrsvo --variants --only stress
"""
import argparse
import pathlib
import sys

from lrsvo_runs import ate_percent, run_lrsvo

EUROC = "../shared/data/euroc_v101_micro"
CONDITIONS = [  # key, what, source, extra options
    ("smooth", "smooth (sim:demo, 30 Hz, 100 m)", "sim:demo", []),
    ("gust", "gusts (10 Hz circuit, 80 m)", "sim:sim/scenarios/gust.yaml", []),
    ("yaw", "yaw steps of 30 and -20 deg (10 Hz, 80 m)", "sim:sim/scenarios/yaw.yaml", []),
    ("strong_gusts", "gusts of 20 deg roll, 11.5 deg pitch (10 Hz, 80 m)", "sim:sim/scenarios/strong_gusts.yaml", []),
    ("rate10", "10 Hz (the demo flight)", "sim:sim/scenarios/rate10.yaml", []),
    ("rate15", "15 Hz (the demo flight)", "sim:sim/scenarios/rate15.yaml", []),
    ("high150", "150 m throughout, 15 Hz", "sim:sim/scenarios/high150.yaml", []),
    ("high150_10hz", "150 m throughout, 10 Hz", "sim:sim/scenarios/high150_10hz.yaml", []),
    ("low30", "30 m, 15 Hz", "sim:sim/scenarios/low30.yaml", []),
    ("low30_10hz", "30 m, 10 Hz", "sim:sim/scenarios/low30_10hz.yaml", []),
    ("low30_30hz", "30 m, 30 Hz", "sim:sim/scenarios/low30_30hz.yaml", []),
    ("exposure", "exposure jumps of +-30 %", "sim:sim/scenarios/exposure.yaml", []),
    ("bad_frames", "blank, corrupt, dropped frames", "sim:sim/scenarios/bad_frames.yaml", []),
    ("dark", "dark frames: 1, 2 and 5 in a row", "sim:sim/scenarios/dark_frames.yaml", []),
    ("gap", "3 s holes: 90 frames dropped, 90 blank", "sim:sim/scenarios/gap.yaml", []),
    ("sensor_vga", "640x480 camera (the demo, 25 Hz)", "sim:sim/scenarios/sensor_vga.yaml", []),
    ("sensor_wide", "752x480 wide-angle camera (60 m, 20 Hz)", "sim:sim/scenarios/sensor_wide.yaml", []),
    ("sensor_noisy", "noisy, blurred, vignetted images (80 m, 20 Hz)", "sim:sim/scenarios/sensor_noisy.yaml", []),
    ("hills", "30 m of relief (100 m, 15 Hz)", "sim:sim/scenarios/hills.yaml", []),
    ("fast", "35 m/s with a turn (100 m, 15 Hz)", "sim:sim/scenarios/fast.yaml", []),
    ("stress", "sim:stress (all of them, 30-150 m)", "sim:stress", []),
    ("euroc", "EuRoC V1_01 (real, still, 1-5 m)", EUROC, ["--min-depth", "0.5"]),
    ("paper", "smooth (sim:paper, 9600 frames, 37-118 m)", "sim:paper", []),  # minutes a run
]


def run(lrsvo, source, extra, out):
    m, failure, wall = run_lrsvo(lrsvo, source, extra, out)
    if m is None:
        return failure, wall
    posed = f"{m['frames_tracked']}/{m['frames']}"
    if m.get("frames_predicted"):
        posed += f" (+{m['frames_predicted']})"
    ate = ate_percent(m)
    if ate is None:
        return f"{posed} posed, no metrics", wall
    ratio = 1.0 + m["path_length_error_percent"] / 100.0 if "path_length_error_percent" in m else float("nan")
    realigned = m.get("frames_realigned", "-")
    relocalised = m.get("frames_relocalised", "-")
    ms = m.get("ms_per_frame", {})
    stages = " | ".join(f"{ms[stage]:.2f}" if stage in ms else "-" for stage in ("detect", "window_adjustment"))
    return (f"{ate:.3f} | {ratio:.4f} | {posed} | {m['segments']} | {realigned} | {relocalised} | {m['fps']:.1f} | "
            f"{stages}"), wall


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--lrsvo", action="append", required=True, help="an lrsvo binary (repeat to compare builds)")
    parser.add_argument("--out", default="robustness", help="folder for every run's outputs")
    parser.add_argument("--variants", action="store_true",
                        help="also run the last build unconstrained (--constraint none) and rigid (--rigid)")
    parser.add_argument("--only", default="", help="comma-separated condition keys: " + ",".join(c[0] for c in CONDITIONS))
    args = parser.parse_args()
    only = set(filter(None, args.only.split(",")))
    out = pathlib.Path(args.out)
    print("| condition | build | ATE (% of distance) | path ratio | frames posed (+predicted) | segments | realigned "
          "| relocalised | fps | detection ms | window ms |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for key, name, source, extra in CONDITIONS:
        if only and key not in only:
            continue
        if source == EUROC and not pathlib.Path(EUROC).exists():
            continue
        runs = [(f"{index}: {lrsvo}", lrsvo, [], str(index)) for index, lrsvo in enumerate(args.lrsvo)]
        if args.variants:
            last = args.lrsvo[-1]
            runs += [(f"{last} --constraint none", last, ["--constraint", "none"], "unconstrained"),
                     (f"{last} --rigid", last, ["--rigid"], "rigid")]
        for label, lrsvo, options, folder in runs:
            row, wall = run(lrsvo, source, extra + options, out / key / folder)
            print(f"| {name} | {label} | {row} |", flush=True)
            print(f"  {key}, {label}: {wall:.0f} s", file=sys.stderr, flush=True)


if __name__ == "__main__":
    main()
