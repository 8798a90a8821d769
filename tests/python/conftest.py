"""Shared fixtures of the Python tests: the travel module from the build tree (PYTHONPATH, set by
CTest), a synthetic LiDAR frame with exact geometry, and the real scans when present."""
import os
import pathlib

import numpy as np
import pytest

travel = pytest.importorskip("travel", reason="the travel module is not on PYTHONPATH "
                             "(run through ctest, or PYTHONPATH=build/python)")


def synthetic_frame(rings=64, columns=1024, height=1.73, seed=0):
    """An HDL-64E-like sweep over flat ground 1.73 m below the sensor, with a 2 x 2 x 2.5 m box
    at x in [8, 10], y in [-1, 1] (its top above the sensor: one face seen); rays that hit
    nothing give (0, 0, 0) (a no-return, invalid).
    Returns (points (N, 4) float32, ring (N,) int, is_box (N,) bool: box points 0.2 m or more
    above the ground)."""
    elevation = np.deg2rad(np.linspace(-24.9, 2.0, rings))
    azimuth = np.linspace(-np.pi, np.pi, columns, endpoint=False)
    el, az = np.meshgrid(elevation, azimuth, indexing="ij")
    d = np.stack([np.cos(el) * np.cos(az), np.cos(el) * np.sin(az), np.sin(el)], axis=-1)
    with np.errstate(divide="ignore", invalid="ignore"):
        t_ground = np.where(d[..., 2] < 0, -height / d[..., 2], np.inf)
        lo = np.array([8.0, -1.0, -height]) - 1e-9
        hi = np.array([10.0, 1.0, -height + 2.5])
        t1, t2 = lo / d, hi / d
        t_near = np.nanmax(np.minimum(t1, t2), axis=-1)
        t_far = np.nanmin(np.maximum(t1, t2), axis=-1)
    hits_box = (t_near <= t_far) & (t_near > 0)
    t = np.where(hits_box, np.minimum(t_near, t_ground), t_ground)
    is_box = hits_box & (t_near <= t_ground)
    t = np.where(t < 80.0, t, 0.0)  # beyond the range: no return
    rng = np.random.default_rng(seed)
    xyz = d * t[..., None] + rng.normal(0, 0.005, d.shape) * (t[..., None] > 0)
    points = np.concatenate([xyz, np.full(t.shape + (1,), 0.5)], axis=-1).reshape(-1, 4)
    ring = np.repeat(np.arange(rings), columns)
    is_box = is_box.reshape(-1) & (t.reshape(-1) > 0) & (points[:, 2] > -height + 0.2)
    return points.astype(np.float32), ring, is_box


@pytest.fixture(scope="session")
def frame():
    return synthetic_frame()


def data_dir():
    return pathlib.Path(os.environ.get("TRAVEL_DATA_DIR", "")) / "semantickitti/sequences/00"


@pytest.fixture(scope="session")
def kitti_sequence():
    seq = data_dir()
    if not os.environ.get("TRAVEL_DATA_DIR") or not (seq / "velodyne/000000.bin").is_file():
        pytest.skip("SemanticKITTI dev frames not found (TRAVEL_DATA_DIR/semantickitti/"
                    "sequences/00): real-data tests skipped")
    return seq
