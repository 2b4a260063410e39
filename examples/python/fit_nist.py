#!/usr/bin/env python3
"""A NIST StRD nonlinear regression fitted with a residual written in Python.

    PYTHONPATH=build/python python3 examples/python/fit_nist.py ../shared/data/nist/Misra1a.dat

Reads the file's data, starting values and certified values, fits y = f(x; b) with the model
named below from both starts (VECTORn parameters, a Python residual with numeric Jacobians)
and prints the correct significant digits of each parameter against the certified ones.
"""

import argparse
import math
import re

import numpy as np

import lrsvo

# A few of the StRD models, by data set name: y = f(b, x).
MODELS = {
    "Misra1a": lambda b, x: b[0] * (1.0 - np.exp(-b[1] * x)),
    "Misra1b": lambda b, x: b[0] * (1.0 - (1.0 + b[1] * x / 2.0) ** -2),
    "Chwirut1": lambda b, x: np.exp(-b[0] * x) / (b[1] + b[2] * x),
    "Chwirut2": lambda b, x: np.exp(-b[0] * x) / (b[1] + b[2] * x),
    "DanWood": lambda b, x: b[0] * x ** b[1],
    "Rat42": lambda b, x: b[0] / (1.0 + np.exp(b[1] - b[2] * x)),
    "Rat43": lambda b, x: b[0] / (1.0 + np.exp(b[1] - b[2] * x)) ** (1.0 / b[3]),
    "Eckerle4": lambda b, x: (b[0] / b[1]) * np.exp(-0.5 * ((x - b[2]) / b[1]) ** 2),
    "MGH09": lambda b, x: b[0] * (x**2 + x * b[1]) / (x**2 + x * b[2] + b[3]),
}


def read_nist(path):
    """The data (x, y), both starts and the certified values of a StRD file."""
    lines = open(path).read().splitlines()
    starts, certified = [], []
    for line in lines:
        match = re.match(r"\s*b\d+\s*=\s*(\S+)\s+(\S+)\s+(\S+)", line)
        if match:
            starts.append((float(match.group(1)), float(match.group(2))))
            certified.append(float(match.group(3)))
    data_at = next(i for i, line in enumerate(lines) if re.match(r"\s*Data:\s+y\s+x", line))
    data = np.array([[float(v) for v in line.split()] for line in lines[data_at + 1 :] if line.strip()])
    return data[:, 1], data[:, 0], np.array(starts).T, np.array(certified)


def correct_digits(estimate, certified):
    relative = abs(estimate - certified) / abs(certified)
    return 15.0 if relative == 0 else max(0.0, -math.log10(relative))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("file", help="a StRD .dat file whose model is one of: " + ", ".join(MODELS))
    args = parser.parse_args()
    name = re.sub(r"\.dat$", "", args.file.split("/")[-1])
    if name not in MODELS:
        parser.error(f"no model for {name}; known: {', '.join(MODELS)}")
    model = MODELS[name]
    x, y, starts, certified = read_nist(args.file)

    for start_index, start in enumerate(starts, 1):
        graph = lrsvo.Graph()
        graph.add_vertex(f"VECTOR{len(start)}", 0, start)
        graph.add_residual([0], lambda b: model(b, x) - y, dimension=len(x))
        summary = graph.optimize("lm_dense", max_iterations=1000, function_tolerance=1e-15,
                                 gradient_tolerance=1e-15, parameter_tolerance=1e-15)
        b = graph.estimate(0)
        digits = [correct_digits(value, truth) for value, truth in zip(b, certified)]
        print(f"{name} start {start_index}: {summary.iterations} iterations, {summary.termination}, "
              f"cost {summary.final_cost:.10g}, fewest correct digits {min(digits):.1f}")
        for i, (value, truth) in enumerate(zip(b, certified), 1):
            print(f"  b{i} = {value:.10e}   certified {truth:.10e}")


if __name__ == "__main__":
    main()
