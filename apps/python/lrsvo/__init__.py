"""lrsvo from Python: graph optimisation with bounds, long-range stereo visual
odometry, and trajectory metrics, with numpy arrays in and out.

The optimiser::

    g = lrsvo.Graph()
    g.add_vertex("POSE_SE2", 0, [0, 0, 0], fixed=True)
    g.add_vertex("POSE_SE2", 1, [0.9, 0.1, 0.0])
    g.add_edge("RELATIVE_POSE_SE2", [0, 1], measurement=[1, 0, 0])
    summary = g.optimize("lm_cholmod")
    summary.to_dict()["final_cost"], g.estimate(1)

The odometry::

    result = lrsvo.run("sim:demo", frames=100, window=12)
    result.trajectory        # N x 8: t, x, y, z, qx, qy, qz, qw (world-from-camera)
    result.metrics["ate_rmse_m"]

help(lrsvo.Graph), help(lrsvo.run), help(lrsvo.Odometry) and docs/python.md say more.
"""

from ._lrsvo import (
    BalProblem,
    Error,
    Graph,
    ParseError,
    Rig,
    Source,
    SolverSummary,
    constraint_methods,
    edge_types,
    load_g2o,
    load_graph,
    read_trajectory,
    robust_kernels,
    solvers,
    trajectory_metrics,
    vertex_types,
    write_trajectory,
)
from ._odometry import Odometry, RunResult, run

__all__ = [
    "BalProblem",
    "Error",
    "Graph",
    "Odometry",
    "ParseError",
    "Rig",
    "RunResult",
    "SolverSummary",
    "Source",
    "constraint_methods",
    "edge_types",
    "load_g2o",
    "load_graph",
    "read_trajectory",
    "robust_kernels",
    "run",
    "solvers",
    "trajectory_metrics",
    "vertex_types",
    "write_trajectory",
]


def _summary_to_dict(summary):
    """The summary as a dict: initial_cost, final_cost, iterations, termination, phase times, per-iteration records."""
    import json

    return json.loads(summary.to_json())


SolverSummary.to_dict = _summary_to_dict
