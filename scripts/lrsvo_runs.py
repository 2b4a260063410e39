"""One `lrsvo run` from a script: the run, its metrics and its ATE, shared by the
scripts that tabulate runs (robustness_table.py, seed_batch.py)."""
import json
import subprocess
import time


def run_lrsvo(lrsvo, source, extra, out):
    """Runs `lrsvo run SOURCE --quiet --no-plot --out OUT EXTRA...`. Returns (metrics, failure,
    wall seconds): the metrics.json it wrote, or None and the last line of its error output."""
    start = time.monotonic()
    result = subprocess.run([lrsvo, "run", str(source), "--quiet", "--no-plot", "--out", str(out), *extra],
                            capture_output=True, text=True)
    wall = time.monotonic() - start
    metrics = out / "metrics.json"
    if result.returncode != 0 or not metrics.exists():
        error = (result.stderr.strip().splitlines() or ["?"])[-1]
        return None, f"fails (exit {result.returncode}): {error[:90]}", wall
    return json.loads(metrics.read_text()), None, wall


def ate_percent(metrics):
    """The ATE in % of the distance flown, or None when the run gave no trajectory metrics."""
    if "ate_rmse_m" not in metrics or not metrics.get("distance_m"):
        return None
    return 100.0 * metrics["ate_rmse_m"] / metrics["distance_m"]
