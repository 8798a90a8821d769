"""The SemanticKITTI dev frames (skipped when absent): labels from Python are byte-identical to
travel-kitti's, and several Pipelines in threads give the serial result."""
import concurrent.futures
import os
import subprocess

import numpy as np
import pytest

import travel

FRAMES = ("000000", "000001", "000002")


def test_labels_identical_to_travel_kitti(kitti_sequence, tmp_path):
    kitti = os.environ.get("TRAVEL_KITTI", "")
    if not os.path.isfile(kitti):
        pytest.skip("travel-kitti not built (TRAVEL_BUILD_MRPT=OFF): nothing to compare with")
    pipeline = travel.Pipeline(travel.Params.from_preset("hdl64"))
    for frame in FRAMES:
        scan_file = kitti_sequence / "velodyne" / f"{frame}.bin"
        subprocess.run([kitti, "-i", str(scan_file), "-o", str(tmp_path / "cpp"), "-q"],
                       check=True, capture_output=True)
        expected = (tmp_path / "cpp" / f"{frame}.label").read_bytes()
        # Both ways in: a Scan (no copy) and a numpy array.
        scan = travel.read_scan(scan_file)
        for points in (scan, scan.points, scan.points.astype(np.float64)):
            result = travel.Pipeline(travel.Params.from_preset("hdl64")).process(points)
            travel.write_labels(tmp_path / "py.label", result)
            assert (tmp_path / "py.label").read_bytes() == expected, frame
        # One Pipeline over consecutive frames, as travel-kitti runs them.
        travel.write_labels(tmp_path / "py.label", pipeline.process(scan))
        assert (tmp_path / "py.label").read_bytes() == expected, frame


def test_metrics_match_travel_kitti(kitti_sequence):
    scan = travel.read_scan(kitti_sequence / "velodyne/000000.bin")
    result = travel.Pipeline(travel.Params.from_preset("hdl64")).process(scan)
    gt = travel.read_labels(kitti_sequence / "labels/000000.label")
    b = travel.metrics.ground(result, gt)
    a = travel.metrics.ground(result, gt, protocol="A", z=scan.points[:, 2])
    o = travel.metrics.objects(result, gt, scan)
    # travel-kitti's line for 000000 (docs/results.md, README).
    assert [round(b[k], 2) for k in ("precision", "recall", "f1", "accuracy")] == \
        [99.01, 99.58, 99.29, 98.99]
    assert round(a["f1"], 2) == 96.93
    assert (round(o["ose_sum"], 2), round(o["use_sum"], 2)) == (12.47, 11.65)
    assert (round(o["mean_coverage"], 3), round(o["mean_purity"], 3)) == (0.954, 0.983)


def test_threads_on_real_frames(kitti_sequence):
    scans = [travel.read_scan(kitti_sequence / "velodyne" / f"{f}.bin") for f in FRAMES]
    params = travel.Params.from_preset("hdl64")
    serial = [travel.Pipeline(params).process(s) for s in scans]

    def run(k):
        return travel.Pipeline(params).process(scans[k % 3].points)

    with concurrent.futures.ThreadPoolExecutor(3) as pool:
        results = list(pool.map(run, range(6)))
    for k, r in enumerate(results):
        assert np.array_equal(r.labels, serial[k % 3].labels)
        assert np.array_equal(r.cluster_ids, serial[k % 3].cluster_ids)


def test_params_are_travel_kittis():
    """Same parameter names, defaults and presets as the CLI: travel-kitti's --print-config
    (its default preset hdl64, then each preset by name) reads back as Params.from_preset."""
    kitti = os.environ.get("TRAVEL_KITTI", "")
    if not os.path.isfile(kitti):
        pytest.skip("travel-kitti not built (TRAVEL_BUILD_MRPT=OFF): nothing to compare with")

    def printed(*args):
        done = subprocess.run([kitti, "--print-config", *args], check=True, capture_output=True,
                              text=True)
        return travel.Params.from_yaml(done.stdout, "travel-kitti --print-config")

    assert printed() == travel.Params.from_preset("hdl64")
    assert printed() != travel.Params()  # the library's defaults: no car box (docs/python.md)
    for name in travel.Params.presets():
        assert printed("-p", name) == travel.Params.from_preset(name), name
    assert printed("--set", "travel.sensor_height=auto").is_auto("sensor_height")
