"""The examples in examples/python run headless, on a synthetic KITTI-like sequence (and on the
SemanticKITTI dev frames when present)."""
import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest

import travel
from conftest import synthetic_frame

EXAMPLES = pathlib.Path(__file__).resolve().parents[2] / "examples" / "python"


def run(script, *args):
    done = subprocess.run([sys.executable, str(EXAMPLES / script), *map(str, args)],
                          capture_output=True, text=True, timeout=300, env=os.environ.copy())
    assert done.returncode == 0, done.stderr
    return done.stdout


@pytest.fixture(scope="module")
def sequence(tmp_path_factory):
    """velodyne/00000k.bin and labels/00000k.label of two synthetic frames."""
    seq = tmp_path_factory.mktemp("sequence")
    (seq / "velodyne").mkdir(), (seq / "labels").mkdir()
    for k in range(2):
        points, _, is_box = synthetic_frame(seed=k)
        points.tofile(seq / "velodyne" / f"{k:06d}.bin")
        gt = np.where(is_box, (3 << 16) | 10, 40).astype(np.uint32)
        gt[(points[:, 2] > -1.6) & ~is_box] = 0
        gt.tofile(seq / "labels" / f"{k:06d}.label")
    return seq


def test_segment_scan(sequence, tmp_path):
    out = tmp_path / "000000.label"
    text = run("segment_scan.py", sequence / "velodyne/000000.bin", "-o", out)
    assert "clusters" in text and out.is_file()
    labels = travel.read_labels(out)
    assert len(labels) == len(travel.read_scan(sequence / "velodyne/000000.bin"))


def test_show_open3d_headless(sequence, tmp_path):
    pytest.importorskip("open3d", reason="python3-open3d is not installed")
    for colour in ("class", "cluster"):
        out = tmp_path / f"{colour}.ply"
        run("show_open3d.py", sequence / "velodyne/000000.bin", "--color", colour, "--save", out)
        assert out.stat().st_size > 1000
    # A file Open3D cannot write fails the script (Open3D itself only prints a warning).
    for bad in (tmp_path / "no-such-folder" / "x.ply", tmp_path / "x.unknown-extension"):
        done = subprocess.run([sys.executable, str(EXAMPLES / "show_open3d.py"),
                               sequence / "velodyne/000000.bin", "--save", bad],
                              capture_output=True, text=True, timeout=300, env=os.environ.copy())
        assert done.returncode != 0 and "could not write" in done.stderr, bad


def test_evaluate_folder(sequence):
    text = run("evaluate_folder.py", sequence)
    assert text.startswith("2 frames: ground F1 ")
    f1 = float(text.split("ground F1 ")[1].split()[0])
    assert f1 > 95


def test_evaluate_folder_on_semantickitti(kitti_sequence):
    text = run("evaluate_folder.py", kitti_sequence)
    # travel-kitti on frames 000000-000002: F1 (B) 99.29, 99.23, 99.30 -> mean 99.27
    assert text.startswith("3 frames: ground F1 99.27 %"), text


def test_readme_example(sequence, tmp_path):
    readme = (pathlib.Path(__file__).resolve().parents[2] / "README.md").read_text()
    code = readme.split("```python\n", 1)[1].split("```", 1)[0]
    assert len(code.strip().splitlines()) == 5
    (tmp_path / "velodyne").mkdir()
    (tmp_path / "velodyne/000000.bin").write_bytes((sequence / "velodyne/000000.bin").read_bytes())
    done = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "000000.label").is_file()
