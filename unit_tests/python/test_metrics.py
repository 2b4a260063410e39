"""Trajectory metrics from Python: the numbers of `lrsvo eval` on the same poses."""

import json
import math

import numpy as np
import pytest

import lrsvo


def circle_flight(seed, poses=400, radius_m=150.0):
    """A level circle flown at 20 m/s with a seeded random walk on the estimate: truth and estimate, N x 8 each."""
    rng = np.random.default_rng(seed)
    t = np.arange(poses) * 0.5
    angle = t * 20.0 / radius_m
    truth = np.zeros((poses, 8))
    truth[:, 0] = t
    truth[:, 1] = radius_m * np.cos(angle)
    truth[:, 2] = radius_m * np.sin(angle)
    truth[:, 3] = 100.0
    truth[:, 6] = np.sin((angle + math.pi / 2) / 2)  # yaw along the circle
    truth[:, 7] = np.cos((angle + math.pi / 2) / 2)
    estimate = truth.copy()
    estimate[:, 1:4] = 1.01 * truth[:, 1:4] + np.cumsum(rng.normal(0.0, 0.05, (poses, 3)), axis=0)
    return estimate, truth


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_metrics_equal_lrsvo_eval(run_cli, tmp_path, seed):
    estimate, truth = circle_flight(seed)
    lrsvo.write_trajectory(str(tmp_path / "estimate.tum"), estimate)
    np.savetxt(tmp_path / "truth.tum", truth, fmt="%.17g")  # numpy's own writer: any TUM file is read alike
    run_cli("eval", tmp_path / "estimate.tum", tmp_path / "truth.tum", "--out", tmp_path / "eval", "--no-plot")
    cli = json.loads((tmp_path / "eval" / "metrics.json").read_text())

    # The files' own numbers, as `lrsvo eval` reads them: the same code on the same doubles, the same figures.
    metrics = lrsvo.trajectory_metrics(np.loadtxt(tmp_path / "estimate.tum"), np.loadtxt(tmp_path / "truth.tum"))
    assert metrics["ate_rmse_m"] > 0.0 and metrics["drift_percent"] > 0.0
    assert_same_figures(cli, metrics, exact=True)

    # read_trajectory hands rotations over as quaternions taken from the matrices it read, a few units of the
    # last place (~1e-16) off the file's. A figure through them moves by that relative amount, an angle theta
    # by ~1e-16 / theta rad (theta > 1e-5 rad here): 1e-9 relative; an angle that is zero (the same rotations
    # in both) is rounding alone, ~1e-14 deg.
    metrics = lrsvo.trajectory_metrics(lrsvo.read_trajectory(str(tmp_path / "estimate.tum")),
                                       lrsvo.read_trajectory(str(tmp_path / "truth.tum")))
    assert_same_figures(cli, metrics, exact=False)


def assert_same_figures(expected, actual, exact, where="metrics"):
    if isinstance(actual, dict):
        assert set(actual) <= set(expected), where
        for key, value in actual.items():
            assert_same_figures(expected[key], value, exact, f"{where}.{key}")
    elif isinstance(actual, list):
        assert len(actual) == len(expected), where
        for index, (e, a) in enumerate(zip(expected, actual)):
            assert_same_figures(e, a, exact, f"{where}[{index}]")
    elif isinstance(actual, float) and not exact:
        assert expected == pytest.approx(actual, rel=1e-9, abs=1e-12), where
    else:
        assert expected == actual, where


def test_a_trajectory_array_reads_back_from_its_file(tmp_path):
    estimate, _ = circle_flight(4, poses=20)
    lrsvo.write_trajectory(str(tmp_path / "estimate.tum"), estimate)
    again = lrsvo.read_trajectory(str(tmp_path / "estimate.tum"))
    # Written with 15 significant digits (as trajectory.tum); the quaternion sign may flip, q and -q alike.
    np.testing.assert_allclose(again[:, :4], estimate[:, :4], rtol=1e-14, atol=1e-12)
    np.testing.assert_allclose(np.abs(again[:, 4:] @ estimate[:, 4:].T).diagonal(), 1.0, rtol=1e-13)


def test_scale_and_ate_of_a_known_error():
    # The estimate is the truth scaled by 1.01 about the origin: Sim3 undoes it exactly.
    _, truth = circle_flight(5)
    scaled = truth.copy()
    scaled[:, 1:4] *= 1.01
    metrics = lrsvo.trajectory_metrics(scaled, truth)
    assert metrics["ate_sim3_rmse_m"] < 1e-9
    assert metrics["scale_error_percent"] == pytest.approx(1.0, abs=1e-9)
    assert metrics["path_length_error_percent"] == pytest.approx(1.0, abs=1e-9)


def test_bad_trajectories_raise():
    _, truth = circle_flight(6, poses=10)
    with pytest.raises(lrsvo.Error, match="N x 8"):
        lrsvo.trajectory_metrics(truth[:, :7], truth)
    zero = truth.copy()
    zero[3, 4:] = 0.0
    with pytest.raises(lrsvo.Error, match="row 3 holds a zero quaternion"):
        lrsvo.trajectory_metrics(zero, truth)
    later = truth.copy()
    later[:, 0] += 1000.0
    with pytest.raises(lrsvo.Error, match="match a true one"):
        lrsvo.trajectory_metrics(later, truth)
    with pytest.raises(lrsvo.Error, match="association"):
        lrsvo.trajectory_metrics(truth, truth, association="nearest")
