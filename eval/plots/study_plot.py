"""Shared helpers of the study plots (eval/plots/<study>.py <outDir>)."""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (the backend is chosen first)


def out_dir():
    """The study's output folder, the script's one argument."""
    if len(sys.argv) != 2:
        sys.exit("usage: %s <study output folder>" % os.path.basename(sys.argv[0]))
    return sys.argv[1]


def number(text):
    """A CSV cell as a float: empty cells (the study's NaN) become NaN; text stays text."""
    if text == "":
        return math.nan
    try:
        return float(text)
    except ValueError:
        return text


def read_csv(folder, name):
    """The rows of a study's CSV as dicts of column -> float (or text)."""
    with open(os.path.join(folder, name), newline="") as f:
        return [{key: number(value) for key, value in row.items()} for row in csv.DictReader(f)]


def columns_like(rows, prefix):
    """The columns whose names start with `prefix`, in file order."""
    return [name for name in rows[0].keys() if name.startswith(prefix)] if rows else []


def figure(panels, width=11.0, height=4.2, rows=1):
    """A figure of `panels` axes on `rows` rows, returned as a flat list."""
    columns = (panels + rows - 1) // rows
    fig, axes = plt.subplots(rows, columns, figsize=(width, height), squeeze=False)
    return fig, [axis for row in axes for axis in row][:panels]


def save(fig, folder, study):
    fig.tight_layout()
    fig.savefig(os.path.join(folder, study + ".png"), dpi=110)
    plt.close(fig)
