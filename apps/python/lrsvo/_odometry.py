"""The odometry from Python: a whole run as `lrsvo run` does it, or frame by frame."""

from dataclasses import dataclass, field
from typing import Any, Dict, List, Optional, Sequence

import numpy as np

from . import _lrsvo


def _option_words(options: Dict[str, Any]) -> List[str]:
    """`lrsvo run`'s option words for keyword options: scale_drift=3e-4 -> --scale-drift 3e-4, rigid=True -> --rigid."""
    words: List[str] = []
    for name, value in options.items():
        flag = "--" + name.replace("_", "-")
        if isinstance(value, bool):
            if value:
                words.append(flag)
        elif value is not None:
            words += [flag, str(value)]
    return words


@dataclass
class RunResult:
    """What a run gives back.

    trajectory: N x 8 (t, x, y, z, qx, qy, qz, qw), the base camera's world-from-camera pose of every
        tracked or predicted frame, as trajectory.tum holds it.
    frames: per input frame, numpy columns as frames.csv holds them (frame, time_s, status, segment,
        keyframe, pose_inliers, window_rms_px, ..., pose N x 8 and extrinsics N x 6k, NaN without a value).
    metrics: metrics.json's dict (frames_tracked, fps, and with ground truth ate_rmse_m, drift_percent, ...).
    truth: the source's true poses over the frames run (N x 8), empty when it has none.
    stopped: Ctrl-C or SIGTERM ended the run early; everything covers the frames done.
    warning: why metrics or plots are missing, if they are.
    """

    trajectory: np.ndarray
    frames: Dict[str, Any]
    metrics: Dict[str, Any] = field(default_factory=dict)
    truth: np.ndarray = field(default_factory=lambda: np.zeros((0, 8)))
    stopped: bool = False
    warning: str = ""

    @property
    def extrinsics(self) -> np.ndarray:
        """The window's S per frame (N x 6 per secondary camera: x, y, z, roll, pitch, yaw); NaN when not tracked."""
        return self.frames["extrinsics"]


def run(
    source: str,
    out: Optional[str] = None,
    *,
    first: int = 0,
    frames: Optional[int] = None,
    plot: bool = True,
    feature_level: bool = False,
    progress: bool = False,
    **options: Any,
) -> RunResult:
    """Runs the odometry on a source, as `lrsvo run SOURCE` does, and returns its results as numpy arrays.

    source: sim:demo | sim:paper | sim:stress | sim:FILE.yaml (rendered on the fly), or a EuRoC or KITTI
        folder (euroc:DIR, kitti:DIR force the layout).
    out: a folder for `lrsvo run`'s files (trajectory.tum, frames.csv, metrics.json, plots); None writes nothing.
    first, frames: start at this frame of the source, stop after this many (None: all).
    plot: write the plots into `out`. feature_level: for sim: sources, the feature-level simulation.
    progress: the CLI's progress line on stderr.
    options: `lrsvo run`'s odometry options by name, with '_' for '-': constraint='gradient_projection',
        rigid=True, window=12, anchors=5, scale_drift=3e-4, extrinsic_rate=1.0, detector='orb', features=300,
        band=8, min_depth=20, outlier_sigmas=..., solver='lm_schur_dense', threads=2, seed=1, on_bad_frame='skip'
        (`lrsvo run --help` explains each). An unknown name or a bad value raises lrsvo.Error.

    The GIL is released while it runs. Ctrl-C (or SIGTERM) stops it after the current frame: the result,
    and the files in `out`, then cover the frames done and `stopped` is True.
    """
    result = _lrsvo._run(
        source,
        "" if out is None else str(out),
        _option_words(options),
        first,
        -1 if frames is None else frames,
        plot,
        feature_level,
        progress,
    )
    return RunResult(**result)


class Odometry:
    """The odometry fed frame by frame from a caller's own loop (a ROS callback, a camera driver).

        vo = lrsvo.Odometry(source.rig, window=12)
        for time_s, images in source:
            for row in vo.process(images, time_s)["pose"]: ...
        result = vo.finish()

    rig: an lrsvo.Rig (lrsvo.Source(...).rig, lrsvo.Rig.paper(), or lrsvo.Rig(cameras, extrinsics)).
    out: a folder for trajectory.tum, extrinsics.csv and frames.csv, streamed as frames are estimated.
    options: `lrsvo run`'s odometry options by name, as lrsvo.run takes them.
    """

    def __init__(self, rig: "_lrsvo.Rig", out: Optional[str] = None, **options: Any) -> None:
        self._odometry = _lrsvo._Odometry(rig, _option_words(options), "" if out is None else str(out))

    def process(self, images: Sequence[np.ndarray], time_s: float) -> Dict[str, Any]:
        """Takes one grey-level (uint8, H x W) image per camera, undistorted, and returns the frames whose
        estimates this call completed, as RunResult.frames' columns: usually this frame, none while an
        initialisation gathers its frames, several when it completes."""
        return self._odometry.process(list(images), float(time_s))

    def finish(self) -> RunResult:
        """Ends the run (frames still held by an initialisation stay without a pose) and returns every frame."""
        return RunResult(**self._odometry.finish())
