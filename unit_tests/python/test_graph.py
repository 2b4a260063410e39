"""The optimiser from Python: graphs by type tag, solves by name, bounds, Python residuals, files, bad input."""

import json
import math
import threading
import time

import numpy as np
import pytest

import lrsvo


def se2_triangle():
    """Three planar poses whose three relative measurements agree: the exact solution has zero cost."""
    g = lrsvo.Graph()
    g.add_vertex("POSE_SE2", 0, [0.0, 0.0, 0.0], fixed=True)
    g.add_vertex("POSE_SE2", 1, [0.8, 0.3, 0.2])
    g.add_vertex("POSE_SE2", 2, [1.2, 0.7, 1.9])
    g.add_edge("RELATIVE_POSE_SE2", [0, 1], measurement=[1.0, 0.0, 0.0])
    g.add_edge("RELATIVE_POSE_SE2", [1, 2], measurement=[0.0, 1.0, math.pi / 2])
    g.add_edge("RELATIVE_POSE_SE2", [0, 2], measurement=[1.0, 1.0, math.pi / 2], information=np.diag([2.0, 2.0, 5.0]))
    return g


def test_a_consistent_pose_graph_is_solved_exactly():
    g = se2_triangle()
    summary = g.optimize("lm_cholmod")
    assert summary.converged, summary.full_report()
    # Zero-residual problem: LM converges quadratically; 1e-9 is far above the rounding of O(1) poses.
    np.testing.assert_allclose(g.estimate(1), [1.0, 0.0, 0.0], atol=1e-9)
    np.testing.assert_allclose(g.estimate(2), [1.0, 1.0, math.pi / 2], atol=1e-9)
    # Residuals within 1e-9 on three edges of information <= 5: a cost below 1/2 * 9 * 5 * 1e-18.
    assert summary.final_cost < 2.5e-17
    report = summary.to_dict()
    assert report["final_cost"] == summary.final_cost
    assert report["iterations"] == summary.iterations
    assert "Termination" in summary.full_report() or summary.termination in summary.full_report()


def test_a_quaternion_measurement_takes_the_residuals_information():
    """EDGE_SE3:QUAT's measurement has 7 values (x y z qx qy qz qw); its information is 6 x 6 by default."""
    g = lrsvo.Graph()
    g.add_vertex("POSE_SE3_QUAT", 0, [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0], fixed=True)
    g.add_vertex("POSE_SE3_QUAT", 1, [0.9, 0.2, -0.1, 0.0, 0.0, math.sin(0.05), math.cos(0.05)])
    half = math.pi / 8  # half of an eighth of a turn about z: the unit quaternion (0, 0, sin, cos)
    g.add_edge("RELATIVE_POSE_SE3_QUAT", [0, 1], measurement=[1.0, 0.0, 0.0, 0.0, 0.0, math.sin(half), math.cos(half)])
    summary = g.optimize("lm_cholmod")
    assert summary.converged, summary.full_report()
    # One edge, zero residual at the solution: 1e-9 is far above rounding on O(1) values.
    np.testing.assert_allclose(g.estimate(1)[:3], [1.0, 0.0, 0.0], atol=1e-9)
    q = g.estimate(1)[3:] / np.linalg.norm(g.estimate(1)[3:])
    assert abs(abs(q @ [0.0, 0.0, math.sin(half), math.cos(half)]) - 1.0) < 1e-12
    with pytest.raises(lrsvo.Error, match="information matrix is 6 x 6"):
        g.add_edge("RELATIVE_POSE_SE3_QUAT", [0, 1], measurement=[0, 0, 0, 0, 0, 0, 1.0], information=np.eye(7))


def test_a_bal_solve_gives_the_cli_final_cost(run_cli, tmp_path):
    # The same generated problem, solver and thread count as the CLI: the same code on the same numbers.
    summary_file = tmp_path / "summary.json"
    run_cli("bal", "--generate", "--cameras", 8, "--points", 400, "--seed", 3, "--json", summary_file)
    cli = json.loads(summary_file.read_text())

    problem = lrsvo.BalProblem.generate(cameras=8, points=400, seed=3)
    graph = problem.graph()
    summary = graph.optimize("lm_schur_cholmod")
    assert summary.initial_cost == cli["initial_cost"]
    assert summary.final_cost == cli["final_cost"]
    assert summary.iterations == cli["iterations"]
    assert summary.ordering == cli["ordering"] and summary.ordering != ""
    assert summary.factorization_flops == cli["factorization_flops"] > 0
    problem.update_from(graph)
    assert problem.rms_reprojection_error() < 2.0  # pixel noise sigma 1: the residual RMS is about 1 at the optimum


def test_bal_problem_round_trips_through_its_file(tmp_path):
    problem = lrsvo.BalProblem.generate(cameras=4, points=50, seed=7)
    path = tmp_path / "problem.txt"
    problem.write(str(path))
    again = lrsvo.BalProblem.read(str(path))
    assert np.array_equal(again.cameras, problem.cameras)
    assert np.array_equal(again.points, problem.points)
    assert np.array_equal(again.observations, problem.observations)
    assert problem.cameras.shape == (4, 9) and problem.points.shape == (50, 3)
    assert problem.observations.shape[1] == 4


def test_a_python_residual_fits_a_curve():
    # y = a exp(b x) + c sampled without noise: the fit must return (a, b, c).
    truth = np.array([2.5, -1.3, 0.4])
    xs = np.linspace(0.0, 3.0, 25)
    ys = truth[0] * np.exp(truth[1] * xs) + truth[2]
    g = lrsvo.Graph()
    g.add_vertex("VECTOR3", 0, [1.0, -0.5, 0.0])  # the parameters (a, b, c)
    g.add_residual([0], lambda p: p[0] * np.exp(p[1] * xs) + p[2] - ys, dimension=len(xs))
    summary = g.optimize("lm_dense")
    assert summary.converged, summary.full_report()
    # Central differences are exact to ~eps^(2/3) relative; a zero-residual fit converges past 1e-8.
    np.testing.assert_allclose(g.estimate(0), truth, rtol=1e-8)


def test_geodesic_acceleration_solves_boxbod_from_its_first_start():
    # NIST's BoxBOD, y = b1 (1 - exp(-b2 x)), from b = (1, 1): plain steps run b2 off to where
    # the model is flat (b1 at the mean of y); accelerated steps reach the certified values.
    xs = np.array([1.0, 2.0, 3.0, 5.0, 7.0, 10.0])
    ys = np.array([109.0, 149.0, 149.0, 191.0, 213.0, 224.0])
    certified = np.array([2.1380940889e02, 5.4723748542e-01])
    estimates = {}
    for accelerated in (False, True):
        g = lrsvo.Graph()
        g.add_vertex("VECTOR2", 0, [1.0, 1.0])
        g.add_residual([0], lambda b: ys - b[0] * (1.0 - np.exp(-b[1] * xs)), dimension=len(xs))
        summary = g.optimize("lm_dense", max_iterations=1000, function_tolerance=1e-15,
                             parameter_tolerance=1e-15, geodesic_acceleration=accelerated)
        estimates[accelerated] = (g.estimate(0), summary)
    plain, summary = estimates[False]
    assert abs(plain[0] - ys.mean()) < 1e-3 * ys.mean(), summary.full_report()
    # Central differences (~1e-10 relative here) and the stopping tolerances leave far more than 4 digits.
    accelerated, summary = estimates[True]
    np.testing.assert_allclose(accelerated, certified, rtol=1e-4, err_msg=summary.full_report())


def test_a_python_residual_matches_the_built_in_edge():
    # The same SE2 measurement as a built-in edge and as a Python residual: the same solution.
    def relative(xi, xj, z):
        c, s = math.cos(xi[2]), math.sin(xi[2])
        d = xj[:2] - xi[:2]
        local = np.array([c * d[0] + s * d[1], -s * d[0] + c * d[1], xj[2] - xi[2]])
        error = local - z
        error[2] = math.atan2(math.sin(error[2]), math.cos(error[2]))
        return error

    built_in = se2_triangle()
    built_in.optimize("lm_cholmod")
    python = lrsvo.Graph()
    for i in range(3):
        python.add_vertex("POSE_SE2", i, se2_triangle().estimate(i), fixed=(i == 0))
    python.add_residual([0, 1], lambda a, b: relative(a, b, np.array([1.0, 0.0, 0.0])), 3)
    python.add_residual([1, 2], lambda a, b: relative(a, b, np.array([0.0, 1.0, math.pi / 2])), 3)
    python.add_residual([0, 2], lambda a, b: relative(a, b, np.array([1.0, 1.0, math.pi / 2])), 3,
                        information=np.diag([2.0, 2.0, 5.0]))
    python.optimize("lm_cholmod")
    for i in (1, 2):
        np.testing.assert_allclose(python.estimate(i), built_in.estimate(i), atol=1e-9)


@pytest.mark.parametrize("method", ["log_barrier", "gradient_projection", "nlopt_lbfgs"])
def test_bounds_hold_under_every_constraint_method(method):
    # A residual pulls x to 5; the bound x < 2 stops it. The minimiser in the box is x = 2 (y, z free at 1, -1).
    g = lrsvo.Graph()
    g.add_vertex("VECTOR3", 7, [0.0, 0.0, 0.0])
    g.add_residual([7], lambda p: p - np.array([5.0, 1.0, -1.0]), 3)
    summary = g.optimize("lm_dense", bounds=[(7, 0, -2.0, 2.0)], constraint=method)
    x = g.estimate(7)
    assert -2.0 <= x[0] <= 2.0, summary.full_report()
    # Every method ends at the active bound; a barrier ends within mu / |gradient| inside it (mu <= 1e-6 at its end).
    assert x[0] > 2.0 - 1e-4, summary.full_report()
    np.testing.assert_allclose(x[1:], [1.0, -1.0], atol=1e-6)


def test_a_start_outside_the_bounds_raises_unless_projected():
    g = lrsvo.Graph()
    g.add_vertex("VECTOR3", 0, [3.0, 0.0, 0.0])
    g.add_residual([0], lambda p: p, 3)
    with pytest.raises(lrsvo.Error, match="vertex 0"):
        g.optimize("lm_dense", bounds=[(0, 0, -1.0, 1.0)], constraint="gradient_projection")
    g.optimize("lm_dense", bounds=[(0, 0, -1.0, 1.0)], constraint="gradient_projection", project_start=True)
    assert abs(g.estimate(0)[0]) <= 1.0


def test_graph_files_round_trip_exactly(tmp_path):
    g = se2_triangle()
    for format, load in (("lrsvo", lrsvo.load_graph), ("g2o", lrsvo.load_g2o)):
        path = tmp_path / f"triangle.{format}"
        g.save(str(path), format=format)
        again = load(str(path))
        assert again.vertex_ids() == g.vertex_ids()
        for i in g.vertex_ids():
            assert np.array_equal(again.estimate(i), g.estimate(i))
        assert again.cost() == g.cost()
        assert again.is_fixed(0)


def test_registries_name_what_the_graph_takes():
    assert {"POSE_SE3", "POINT3", "STEREO_EXTRINSIC", "SCALE", "BAL_CAMERA", "POSE_SE2"} <= set(lrsvo.vertex_types())
    assert {"PROJECT_BASE", "PROJECT_SECONDARY", "BAL_PROJECTION", "RELATIVE_POSE_SE3_QUAT"} <= set(lrsvo.edge_types())
    assert "lm_schur_cholmod" in lrsvo.solvers()
    assert {"log_barrier", "gradient_projection", "none"} <= set(lrsvo.constraint_methods())
    assert "Huber" in lrsvo.robust_kernels()


def test_bad_input_raises_with_the_libraries_messages(tmp_path):
    g = lrsvo.Graph()
    with pytest.raises(lrsvo.Error, match="unknown name 'NOT_A_TYPE'"):
        g.add_vertex("NOT_A_TYPE", 0, [0.0])
    with pytest.raises(lrsvo.Error, match="an estimate has 3 values, got 2"):
        g.add_vertex("POINT3", 0, [0.0, 1.0])
    with pytest.raises(lrsvo.Error, match="not finite"):
        g.add_vertex("POINT3", 0, [0.0, math.nan, 1.0])
    g.add_vertex("POSE_SE2", 0, [0.0, 0.0, 0.0])
    g.add_vertex("POSE_SE2", 1, [1.0, 0.0, 0.0])
    with pytest.raises(lrsvo.Error):
        g.add_vertex("POSE_SE2", 1, [1.0, 0.0, 0.0])  # duplicate id
    with pytest.raises(lrsvo.Error, match="no vertex 5"):
        g.add_edge("RELATIVE_POSE_SE2", [0, 5], measurement=[1.0, 0.0, 0.0])
    with pytest.raises(lrsvo.Error, match="joins 2 vertices, got 1"):
        g.add_edge("RELATIVE_POSE_SE2", [0], measurement=[1.0, 0.0, 0.0])
    with pytest.raises(lrsvo.Error, match="reads 3 values of parameters and measurement, got 0 \\+ 4"):
        g.add_edge("RELATIVE_POSE_SE2", [0, 1], measurement=[1.0, 0.0, 0.0, 4.0])
    with pytest.raises(lrsvo.Error, match="got 0 \\+ 2"):
        g.add_edge("RELATIVE_POSE_SE2", [0, 1], measurement=[1.0, 0.0])
    with pytest.raises(lrsvo.Error, match="information matrix is 3 x 3"):
        g.add_edge("RELATIVE_POSE_SE2", [0, 1], measurement=[1.0, 0.0, 0.0], information=np.eye(4))
    with pytest.raises(lrsvo.Error, match="positive definite"):
        g.add_edge("RELATIVE_POSE_SE2", [0, 1], measurement=[1.0, 0.0, 0.0], information=-np.eye(3))
    with pytest.raises(lrsvo.Error, match="unknown name"):
        g.optimize("lm_no_such_solver")
    assert g.edge_count == 0

    g.add_residual([0, 1], lambda a, b: np.zeros(2), dimension=3)
    with pytest.raises(lrsvo.Error, match="returned 2 values; its dimension is 3"):
        g.optimize("lm_dense")
    with pytest.raises(lrsvo.Error, match="cannot be saved"):
        g.save(str(tmp_path / "python.graph"))

    def fails(a, b):
        raise ZeroDivisionError("from the model")

    h = lrsvo.Graph()
    h.add_vertex("POINT3", 0, [0.0, 0.0, 0.0])
    h.add_vertex("POINT3", 1, [0.0, 0.0, 0.0])
    h.add_residual([0, 1], fails, dimension=1)
    with pytest.raises(ZeroDivisionError, match="from the model"):
        h.optimize("lm_dense")

    broken = tmp_path / "broken.graph"
    broken.write_text("VERTEX POINT3 0 0 0 1.0 2.0\n")
    with pytest.raises(lrsvo.ParseError, match="broken.graph:1"):
        lrsvo.load_graph(str(broken))


def test_a_solve_releases_the_gil():
    """While a solve runs in another thread, this one keeps running Python."""
    problem = lrsvo.BalProblem.generate(cameras=30, points=6000, seed=5)
    graph = problem.graph()
    done = {}

    def solve():
        start = time.perf_counter()
        done["summary"] = graph.optimize("lm_schur_cholmod", max_iterations=20)
        done["seconds"] = time.perf_counter() - start

    worker = threading.Thread(target=solve)
    ticks = [time.perf_counter()]
    worker.start()
    while worker.is_alive():
        ticks.append(time.perf_counter())
    worker.join()
    assert done["summary"].final_cost < done["summary"].initial_cost
    # Holding the GIL, the solve would stop this loop for its whole length; released, this thread waits at most
    # a switch interval (5 ms) and the scheduler's delays on a loaded machine, far below half the solve.
    assert done["seconds"] > 0.05
    assert max(np.diff(ticks)) < 0.5 * done["seconds"]
