#!/usr/bin/env python3
"""Runs `lrsvo run` on simulated flights in other worlds: for each source and seed N, the
same scenario with every seed it has (the scenario's, the flight's, the terrain's, the
rig deformation's and the texture's) set to N, so one claim is checked over a batch of
worlds rather than on one. Prints one Markdown row per flight, seed and build (ATE in %
of the distance flown, KITTI drift, frames posed, segments), then per source and build
the mean and median ATE and the mean KITTI drift and, against the first build, the seeds
where it is better, equal or worse (equal: the same ATE to the printed digits).

Give one `--lrsvo` per build to compare; the builds take turns on each seed. Options
after `--` go to every run. Run from the repository's top:

    scripts/seed_batch.py --lrsvo build/bin/lrsvo --source sim:demo --seeds 1-6
    scripts/seed_batch.py --lrsvo OLD/bin/lrsvo --lrsvo build/bin/lrsvo \\
        --source sim:demo --source sim:sim/scenarios/gust.yaml --seeds 1-6 --out seeds
    scripts/seed_batch.py --lrsvo build/bin/lrsvo --source sim:demo --seeds 2,3 -- --constraint none

The scenario files each run read are written beside its outputs (OUT/<flight>_s<N>.yaml).
"""
import argparse
import pathlib
import re
import statistics
import sys

from lrsvo_runs import ate_percent, run_lrsvo

COMPONENTS = ("flight", "terrain", "deformation", "texture")  # the scenario's parts that draw from a seed


def parse_seeds(text):
    seeds = []
    for part in filter(None, text.split(",")):
        first, _, last = part.partition("-")
        seeds += range(int(first), int(last or first) + 1)
    if not seeds:
        raise argparse.ArgumentTypeError("no seeds in " + repr(text))
    return seeds


def reseeded(text, seed, name):
    """The scenario file `text` with every seed set to `seed` and its name set to `name`."""
    lines = [line for line in text.splitlines() if not re.match(r"(seed|name)\s*:", line)]
    out, pending, block_indent = [], set(COMPONENTS), None
    for index, line in enumerate(lines):
        if line and not line[0].isspace():
            block_indent = None  # a top-level line ends any component's block
        key = re.match(r"(\w+)\s*:\s*(.*)$", line)
        if key and key.group(1) in COMPONENTS:
            component, rest = key.groups()
            pending.discard(component)
            if rest.startswith("{"):  # a flow map: its seed replaced or added
                inner = re.sub(r"\bseed\s*:\s*[^,}]+,?\s*", "", rest[1:].rstrip().rstrip("}")).strip().rstrip(",").strip()
                out.append(f"{component}: {{ seed: {seed}{', ' + inner if inner else ''} }}")
                continue
            if not rest:  # a block map: the seed at its first child's indentation
                child = next((l for l in lines[index + 1:] if l.strip() and not l.lstrip().startswith("#")), "  ")
                block_indent = child[:len(child) - len(child.lstrip())] or "  "
                out += [line, f"{block_indent}seed: {seed}"]
                continue
        if block_indent is not None and re.match(re.escape(block_indent) + r"seed\s*:", line):
            continue  # the block's own seed, replaced above
        out.append(line)
    header = [out.pop(0)] if out and out[0].startswith("%YAML") else ["%YAML:1.0"]
    tail = [f"name: {name}", f"seed: {seed}"] + [f"{c}: {{ seed: {seed} }}" for c in COMPONENTS if c in pending]
    return "\n".join(header + out + tail) + "\n"


def scenario_text(source):
    """The text of a `sim:` source: a file's, or a built-in's name as the base."""
    if not source.startswith("sim:"):
        sys.exit(f"seed_batch: {source} is not a simulated flight (sim:NAME or sim:FILE.yaml)")
    target = source[len("sim:"):]
    path = pathlib.Path(target)
    if path.suffix in (".yaml", ".yml"):
        if not path.exists():
            sys.exit(f"seed_batch: no scenario file {path}")
        return path.stem, path.read_text()
    return target, f"%YAML:1.0\nbase: {target}\n"


def run(lrsvo, scenario, extra, out):
    """(ATE %, KITTI drift % or None, the table row's cells)."""
    m, failure, _ = run_lrsvo(lrsvo, f"sim:{scenario}", extra, out)
    if m is None:
        return None, None, failure
    ate = ate_percent(m)
    if ate is None:
        return None, None, f"{m['frames_tracked']}/{m['frames']} posed, no metrics"
    drift = m.get("drift_percent")
    drift_cell = f"{drift:.3f} %" if drift is not None else "–"
    return ate, drift, f"{ate:.3f} % | {drift_cell} | {m['frames_tracked']}/{m['frames']} | {m['segments']}"


def summarise(flight, builds, ates, drifts):
    for index, lrsvo in enumerate(builds):
        values = [a for a in ates[index] if a is not None]
        if not values:
            print(f"{flight}, {index}: {lrsvo}: no run gave an ATE")
            continue
        line = (f"{flight}, {index}: {lrsvo}: ATE mean {statistics.mean(values):.3f} %, "
                f"median {statistics.median(values):.3f} % over {len(values)} seeds")
        drift_values = [d for d in drifts[index] if d is not None]
        if drift_values:
            line += f", KITTI drift mean {statistics.mean(drift_values):.3f} %"
        if index > 0:
            pairs = [(round(a, 3), round(b, 3)) for a, b in zip(ates[0], ates[index]) if a is not None and b is not None]
            line += (f"; against 0: better on {sum(b < a for a, b in pairs)}, equal on {sum(b == a for a, b in pairs)}, "
                     f"worse on {sum(b > a for a, b in pairs)}")
        print(line)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--lrsvo", action="append", required=True, help="an lrsvo binary (repeat to compare builds)")
    parser.add_argument("--source", action="append", required=True,
                        help="a simulated flight: sim:demo, sim:paper, sim:stress or sim:FILE.yaml (repeat for more)")
    parser.add_argument("--seeds", type=parse_seeds, default=parse_seeds("1-5"),
                        help="seeds as a list and ranges, e.g. 1-6 or 2,4,7 (default 1-5)")
    parser.add_argument("--out", default="seed_batch", help="folder for the scenario files and every run's outputs")
    parser.add_argument("extra", nargs="*", help="options after -- for every run, e.g. -- --constraint none")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    print("| flight | seed | build | ATE (% of distance) | KITTI drift | frames posed | segments |")
    print("|---|---|---|---|---|---|---|")
    summaries = []
    for source in args.source:
        flight, text = scenario_text(source)
        ates = [[] for _ in args.lrsvo]
        drifts = [[] for _ in args.lrsvo]
        for seed in args.seeds:
            name = f"{flight}_s{seed}"
            scenario = out / f"{name}.yaml"
            scenario.write_text(reseeded(text, seed, name))
            for index, lrsvo in enumerate(args.lrsvo):
                ate, drift, row = run(lrsvo, scenario, args.extra, out / name / str(index))
                ates[index].append(ate)
                drifts[index].append(drift)
                print(f"| {flight} | {seed} | {index}: {lrsvo} | {row} |", flush=True)
        summaries.append((flight, ates, drifts))
    print()
    for flight, ates, drifts in summaries:
        summarise(flight, args.lrsvo, ates, drifts)


if __name__ == "__main__":
    main()
