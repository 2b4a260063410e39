#!/usr/bin/env python3
"""What calling lrsvo from Python costs next to the same work in C++, in one script.

    PYTHONPATH=build/python python3 scripts/bench_python.py --lrsvo build/bin/lrsvo

Prints, each as the median of --repeat runs:
  1. a BAL solve: Python's Graph.optimize (wall, around the call) against the solver's own time
     and against `lrsvo bal` on the same generated problem;
  2. building that graph vertex by vertex and edge by edge from Python against BalProblem.graph();
  3. a residual written in Python against the built-in edge of the same model (a planar pose chain);
  4. lrsvo.run against `lrsvo run` on the first frames of sim:demo (both render the frames).
"""

import argparse
import json
import math
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np

import lrsvo


def median_time(function, repeat):
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        result = function()
        times.append(time.perf_counter() - start)
    return statistics.median(times), result


def bal(args, scratch):
    options = dict(cameras=args.cameras, points=args.points, seed=1)
    summary_file = scratch / "bal.json"
    cli_wall, _ = median_time(
        lambda: subprocess.run([args.lrsvo, "bal", "--generate", "--cameras", str(args.cameras), "--points",
                                str(args.points), "--seed", "1", "--json", str(summary_file)],
                               check=True, capture_output=True),
        args.repeat)
    cli = json.loads(summary_file.read_text())

    def solve():
        graph = lrsvo.BalProblem.generate(**options).graph()
        start = time.perf_counter()
        summary = graph.optimize("lm_schur_cholmod")
        return time.perf_counter() - start, summary

    walls, inner = [], []
    for _ in range(args.repeat):
        wall, summary = solve()
        walls.append(wall)
        inner.append(summary.total_seconds)
    wall, solver = statistics.median(walls), statistics.median(inner)
    observations = len(lrsvo.BalProblem.generate(**options).observations)
    print(f"1. BAL solve, {args.cameras} cameras, {args.points} points, {observations} observations:")
    print(f"   Graph.optimize from Python {wall:.4f} s, the solver's own time {solver:.4f} s "
          f"(call overhead {1e3 * (wall - solver):.2f} ms, ratio {wall / solver:.3f})")
    print(f"   lrsvo bal: solver {cli['total_time_s']:.4f} s, the whole program {cli_wall:.4f} s; same final cost: "
          f"{cli['final_cost'] == summary.final_cost}")
    return options


def building(args, options):
    problem = lrsvo.BalProblem.generate(**options)
    cameras, points, observations = problem.cameras, problem.points, problem.observations

    def by_python():
        g = lrsvo.Graph()
        for i, camera in enumerate(cameras):
            g.add_vertex("BAL_CAMERA", i, camera)
        offset = len(cameras)
        for j, point in enumerate(points):
            g.add_vertex("POINT3", offset + j, point, marginalized=True)
        for camera, point, x, y in observations:
            g.add_edge("BAL_PROJECTION", [int(camera), offset + int(point)], measurement=[x, y])
        return g

    python_time, g = median_time(by_python, args.repeat)
    cpp_time, h = median_time(problem.graph, args.repeat)
    items = len(cameras) + len(points) + len(observations)
    print(f"2. Building that graph ({items} vertices and edges): from Python {python_time:.3f} s "
          f"({1e6 * python_time / items:.1f} us each), BalProblem.graph() {cpp_time:.4f} s: ratio "
          f"{python_time / cpp_time:.1f}; same cost: {g.cost() == h.cost()}")


def python_residual(args):
    poses = args.poses
    rng = np.random.default_rng(1)
    steps = np.column_stack([np.ones(poses - 1), np.zeros(poses - 1), np.full(poses - 1, 0.05)])
    start = [np.array([0.0, 0.0, 0.0])]
    for step in steps:
        x, y, theta = start[-1]
        start.append(np.array([x + math.cos(theta) * step[0], y + math.sin(theta) * step[0], theta + step[2]]))
    noisy = [s + rng.normal(0.0, 0.1, 3) * (i > 0) for i, s in enumerate(start)]

    def relative(xi, xj, z):
        c, s = math.cos(xi[2]), math.sin(xi[2])
        dx, dy = xj[0] - xi[0], xj[1] - xi[1]
        e = np.array([c * dx + s * dy - z[0], -s * dx + c * dy - z[1], xj[2] - xi[2] - z[2]])
        e[2] = math.atan2(math.sin(e[2]), math.cos(e[2]))
        return e

    def chain(python):
        g = lrsvo.Graph()
        for i, pose in enumerate(noisy):
            g.add_vertex("POSE_SE2", i, pose, fixed=(i == 0))
        for i, z in enumerate(steps):
            if python:
                g.add_residual([i, i + 1], lambda a, b, z=z: relative(a, b, z), 3)
            else:
                g.add_edge("RELATIVE_POSE_SE2", [i, i + 1], measurement=z)
        return g

    def solve(python):
        g = chain(python)
        start_time = time.perf_counter()
        summary = g.optimize("lm_cholmod")
        return time.perf_counter() - start_time, summary

    built_in = statistics.median(solve(False)[0] for _ in range(args.repeat))
    python_runs = [solve(True) for _ in range(args.repeat)]
    in_python = statistics.median(t for t, _ in python_runs)
    summary = python_runs[0][1]
    print(f"3. A pose chain of {poses} poses: built-in edges {built_in:.4f} s, the same model as Python residuals "
          f"{in_python:.3f} s ({summary.iterations} iterations): ratio {in_python / built_in:.0f}")


def odometry(args, scratch):
    frames = str(args.frames)
    cli_wall, _ = median_time(
        lambda: subprocess.run([args.lrsvo, "run", "sim:demo", "--frames", frames, "--no-plot", "--quiet", "--out",
                                str(scratch / "cli_run")], check=True, capture_output=True),
        args.repeat)
    python_wall, result = median_time(
        lambda: lrsvo.run("sim:demo", out=str(scratch / "python_run"), frames=args.frames, plot=False),
        args.repeat)
    same = (scratch / "cli_run" / "trajectory.tum").read_bytes() == (scratch / "python_run" / "trajectory.tum").read_bytes()
    print(f"4. sim:demo, {args.frames} frames rendered and run: lrsvo.run {python_wall:.2f} s, lrsvo run "
          f"{cli_wall:.2f} s: ratio {python_wall / cli_wall:.3f}; same trajectory.tum: {same}")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--lrsvo", default="build/bin/lrsvo", help="the lrsvo program (default build/bin/lrsvo)")
    parser.add_argument("--cameras", type=int, default=20)
    parser.add_argument("--points", type=int, default=4000)
    parser.add_argument("--poses", type=int, default=300, help="poses of the chain in 3 (default 300)")
    parser.add_argument("--frames", type=int, default=60, help="frames of sim:demo in 4 (default 60)")
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        scratch = Path(folder)
        options = bal(args, scratch)
        building(args, options)
        python_residual(args)
        odometry(args, scratch)


if __name__ == "__main__":
    main()
