"""The odometry from Python: a run gives the CLI's trajectory bit for bit; frame by frame gives the run's."""

import signal
import subprocess
import sys
import time

import numpy as np
import pytest

import lrsvo

FRAMES = 40  # the rendered demo flight initialises within its first second (30 Hz) and tracks on


@pytest.fixture(scope="module")
def python_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("python_run")
    return out, lrsvo.run("sim:demo", out=str(out), frames=FRAMES, plot=False)


def test_a_run_gives_the_cli_trajectory_bit_for_bit(run_cli, tmp_path, python_run):
    out, result = python_run
    run_cli("run", "sim:demo", "--frames", FRAMES, "--out", tmp_path / "cli", "--no-plot", "--quiet")
    cli_file = (tmp_path / "cli" / "trajectory.tum").read_bytes()
    assert (out / "trajectory.tum").read_bytes() == cli_file
    assert (out / "extrinsics.csv").read_bytes() == (tmp_path / "cli" / "extrinsics.csv").read_bytes()

    # The arrays hold the poses before the file's 15 significant digits.
    cli = np.loadtxt(tmp_path / "cli" / "trajectory.tum")
    assert len(result.trajectory) == len(cli) > FRAMES // 2
    np.testing.assert_allclose(result.trajectory[:, :4], cli[:, :4], rtol=1e-14, atol=1e-12)
    signs = np.sign(np.sum(result.trajectory[:, 4:] * cli[:, 4:], axis=1))
    np.testing.assert_allclose(result.trajectory[:, 4:] * signs[:, None], cli[:, 4:], atol=1e-14)


def test_a_run_reports_frames_and_metrics(python_run):
    _, result = python_run
    frames = result.frames
    assert len(frames["frame"]) == FRAMES
    assert list(frames["frame"]) == list(range(FRAMES))
    tracked = np.array([s == "tracked" for s in frames["status"]])
    assert tracked.sum() == result.metrics["frames_tracked"] == len(result.trajectory)
    assert np.all(np.isnan(frames["pose"][~tracked, 1:]))
    np.testing.assert_array_equal(frames["pose"][tracked], result.trajectory)
    assert result.extrinsics.shape == (FRAMES, 6)
    assert np.all(np.isfinite(result.extrinsics[tracked]))
    assert result.truth.shape == (FRAMES, 8)
    assert result.metrics["ate_rmse_m"] >= 0.0 and not result.stopped
    # The metrics from the arrays equal the run's own.
    metrics = lrsvo.trajectory_metrics(result.trajectory, result.truth)
    assert metrics["ate_rmse_m"] == result.metrics["ate_rmse_m"]


def test_frame_by_frame_gives_the_runs_trajectory(python_run):
    _, result = python_run
    source = lrsvo.Source("sim:demo")
    vo = lrsvo.Odometry(source.rig)
    completed = 0
    for index, (time_s, images) in enumerate(source):
        if index == FRAMES:
            break
        assert len(images) == 2 and images[0].dtype == np.uint8 and images[0].ndim == 2
        completed += len(vo.process(images, time_s)["frame"])
    finished = vo.finish()
    assert completed <= FRAMES == len(finished.frames["frame"])
    np.testing.assert_array_equal(finished.trajectory, result.trajectory)


def test_options_by_name_and_bad_ones():
    rigid = lrsvo.run("sim:demo", frames=12, plot=False, rigid=True, window=12, seed=2)
    assert len(rigid.frames["frame"]) == 12
    with pytest.raises(lrsvo.Error, match="unknown odometry option 'no_such_option' \\(known: .*scale_drift"):
        lrsvo.run("sim:demo", frames=5, no_such_option=3)
    with pytest.raises(lrsvo.Error, match="window"):
        lrsvo.run("sim:demo", frames=5, window=-2)
    with pytest.raises(lrsvo.Error):
        lrsvo.run("no/such/folder", frames=5)
    rig = lrsvo.Rig.paper()
    vo = lrsvo.Odometry(rig)
    with pytest.raises(lrsvo.Error, match="the rig has 2 cameras, got 1 images"):
        vo.process([np.zeros((960, 1280), np.uint8)], 0.0)
    with pytest.raises(lrsvo.Error, match="rig: no camera"):
        lrsvo.Rig(cameras=[], extrinsics=[])


def test_ctrl_c_stops_a_run_after_the_current_frame_with_whole_files(tmp_path):
    """SIGINT to a Python process inside lrsvo.run: the run stops, returns, and its files are whole."""
    out = tmp_path / "run"
    script = (
        "import sys, lrsvo\n"
        "r = lrsvo.run('sim:demo', out=sys.argv[1], frames=600, plot=False)\n"
        "print('stopped', r.stopped, len(r.frames['frame']), flush=True)\n"
    )
    process = subprocess.Popen([sys.executable, "-c", script, str(out)], stdout=subprocess.PIPE, text=True)
    frames_csv = out / "frames.csv"
    deadline = time.monotonic() + 120.0
    while time.monotonic() < deadline and process.poll() is None:
        if frames_csv.exists() and frames_csv.read_text().count("\n") > 20:
            break
        time.sleep(0.05)
    assert process.poll() is None, "the run ended before it could be interrupted"
    process.send_signal(signal.SIGINT)
    stdout, _ = process.communicate(timeout=120)
    assert process.returncode == 0, stdout
    word, stopped, frames = stdout.split()
    assert (word, stopped) == ("stopped", "True") and 20 <= int(frames) < 600
    lines = frames_csv.read_text().splitlines(keepends=True)
    assert all(line.endswith("\n") for line in lines)
    assert len({line.count(",") for line in lines}) == 1
    assert len(lines) == int(frames) + 1  # the header, then one line per frame done
    assert (out / "metrics.json").exists()
