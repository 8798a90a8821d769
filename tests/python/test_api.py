"""travel's Python API on synthetic frames: shapes and dtypes, every input layout giving the same
labels, parameters, files, metrics, errors and threads."""
import concurrent.futures
import copy
import multiprocessing
import pickle
import struct

import numpy as np
import pytest

import travel
from conftest import synthetic_frame


def segment(points, **kwargs):
    return travel.Pipeline(travel.Params()).process(points, **kwargs)


def test_result_shapes_and_dtypes(frame):
    points, _, is_box = frame
    r = segment(points)
    n = len(points)
    assert r.labels.shape == (n,) and r.labels.dtype == np.uint8
    assert r.cluster_ids.shape == (n,) and r.cluster_ids.dtype == np.uint32
    assert r.ground_mask.dtype == np.bool_ and r.ground_mask.sum() == r.class_counts["ground"]
    assert sum(r.class_counts.values()) == n
    assert set(np.unique(r.labels)) <= {0, 1, 2, 3}
    # Ground is ground, the box is one cluster.
    ground = (points[:, 2] < -1.6) & (np.hypot(points[:, 0], points[:, 1]) < 40)
    assert np.mean(r.labels[ground] == travel.GROUND) > 0.95
    assert np.all(r.labels[is_box] == travel.NONGROUND)
    box_ids = np.unique(r.cluster_ids[is_box])
    assert len(box_ids) == 1 and box_ids[0] > 0
    c = r.clusters
    k = len(c)
    assert k >= 1 and np.array_equal(c.ids, np.arange(1, k + 1))
    for name in ("centroids", "aabb_min", "aabb_max", "obb_center", "obb_extent"):
        assert getattr(c, name).shape == (k, 3) and getattr(c, name).dtype == np.float32
    for name in ("num_points", "first_point", "obb_yaw", "ground_z", "height_above_ground"):
        assert getattr(c, name).shape == (k,)
    box = box_ids[0] - 1
    assert c.num_points[box] == np.sum(r.cluster_ids == box_ids[0])
    assert 7.9 < c.centroids[box, 0] < 8.1  # the one face seen
    assert abs(c.height_above_ground[box] - (points[is_box, 2].max() + 1.73)) < 0.05
    t = r.terrain
    m = len(t)
    assert m == 4 * t.cells_per_side ** 2 and t.resolution == 4.0
    assert t.planes.shape == (m, 4) and t.ground_planes.shape == (m, 4)
    assert t.corners.shape == (m, 3, 3) and t.means.shape == (m, 3)
    assert t.traversable.dtype == np.bool_ and t.traversable.sum() > 0
    assert t.node_class.dtype == np.uint8 and t.num_points.sum() > 0
    node = t.node_at(5.0, 0.5)
    assert t.traversable[node] and abs(t.ground_planes[node, 3] - 1.73) < 0.05
    h = t.height_above_ground(np.array([[5.0, 0.5, -1.0]]))
    assert abs(h[0] - 0.73) < 0.05
    assert {"preprocess", "ground_total", "objects_total", "total"} <= set(r.timings)
    assert abs(r.sensor_height - 1.73) < 1e-9 and "ground" in repr(r)


def test_every_layout_gives_the_same_labels(frame):
    points, ring, _ = frame
    reference = segment(points)
    layouts = {
        "float64": points.astype(np.float64),
        "xyz only": np.ascontiguousarray(points[:, :3]),
        "fortran": np.asfortranarray(points),
        "strided view": np.concatenate([points, points], axis=1)[:, :4],
        "column slice": points[:, :3],
    }
    for name, p in layouts.items():
        r = segment(p)
        assert np.array_equal(r.labels, reference.labels), name
        assert np.array_equal(r.cluster_ids, reference.cluster_ids), name
    with_rings = segment(points, rings=ring.astype(np.uint16))
    assert np.array_equal(with_rings.labels, reference.labels)


def test_nan_points_are_invalid_not_errors(frame):
    points = frame[0].copy()
    points[:100, 0] = np.nan
    points[100:200, 2] = np.inf
    r = segment(points)
    assert np.all(r.labels[:200] == travel.INVALID) and np.all(r.cluster_ids[:200] == 0)


def test_pipeline_keeps_state_and_reports_auto_height(frame):
    params = travel.Params(sensor_height="auto")
    assert params.is_auto("sensor_height") and not params.is_auto("mount_roll_deg")
    pipeline = travel.Pipeline(params)
    first = pipeline.process(frame[0])
    assert "sensor_height" in first.mount_note
    assert abs(pipeline.params.sensor_height - 1.73) < 0.05
    assert pipeline.process(frame[0]).mount_note == ""


def test_input_errors(frame):
    points = frame[0]
    pipeline = travel.Pipeline(travel.Params())
    bad = {
        "ndim": points[:, 0],
        "columns": points[:, :2],
        "dtype": points.astype(np.int32),
        "float16": points.astype(np.float16),
    }
    for name, p in bad.items():
        with pytest.raises(ValueError, match="points"):
            pipeline.process(p)
    with pytest.raises(ValueError, match="rings"):
        pipeline.process(points, rings=np.zeros(3, np.uint16))
    with pytest.raises(ValueError, match="rings"):
        pipeline.process(points, rings=np.full(len(points), 70000))
    with pytest.raises(ValueError, match="rings"):
        pipeline.process(points, rings=np.zeros(len(points), np.float32))
    with pytest.raises(ValueError, match="times"):
        pipeline.process(points, times=np.zeros(len(points) - 1, np.float32))
    with pytest.raises(ValueError, match="attitude"):
        pipeline.process(points, attitude=np.eye(2))
    with pytest.raises(ValueError, match="velocity"):
        pipeline.process(points, velocity=[1, 2, 3])
    times = np.zeros(len(points), np.float32)
    with pytest.raises(ValueError, match=r"velocity \(.*\): not finite"):
        pipeline.process(points, times=times, velocity=[np.nan, 0, 0, 0, 0, 0])
    with pytest.raises(ValueError, match="reference_time: not finite"):  # silently no deskew
        pipeline.process(points, times=times, velocity=np.ones(6), reference_time=np.nan)
    # An empty frame is not an error: nothing to label.
    assert len(pipeline.process(np.zeros((0, 3), np.float32)).labels) == 0


def test_attitude_and_deskew_inputs(frame):
    points, _, _ = frame
    level = segment(points, attitude=np.eye(3), gravity=None)
    assert np.array_equal(level.labels, segment(points).labels)
    times = np.linspace(0, 0.1, len(points), dtype=np.float32)
    still = segment(points, times=times, velocity=np.zeros(6))
    assert np.array_equal(still.labels, level.labels)
    # Absolute float64 stamps (ROS, UNIX time) deskew as the same times relative to the sweep:
    # in float32 (the library's per-point time) 1.7e9 s has a 128 s step and every dt was 0.
    relative = np.linspace(0, 0.1, len(points))
    moving = [5.0, 0, 0, 0, 0, 0.5]
    deskewed = segment(points, times=(relative - 0.05).astype(np.float32), velocity=moving)
    assert not np.array_equal(deskewed.labels, level.labels)  # the motion matters here
    t0 = 1.7e9
    stamped = segment(points, times=t0 + relative, velocity=moving, reference_time=t0 + 0.05)
    assert np.array_equal(stamped.labels, deskewed.labels)


def test_params_attributes_come_from_the_library():
    p = travel.Params()
    keys = travel.Params.keys()
    assert len(keys) > 40 and "sensor_height" in keys and "ground_dist" in keys
    for key in keys:
        doc = getattr(travel.Params, key).__doc__
        assert doc and len(doc) > 20, key
        getattr(p, key)
    assert "[m]" in travel.Params.sensor_height.__doc__
    assert p.to_dict()["num_rings"] == 64
    p.ground_dist = 0.2
    p.num_rings = 32
    p.ring_source = "table"
    p.deskew = False
    assert (p.ground_dist, p.num_rings, p.ring_source, p.deskew) == (0.2, 32, "table", False)
    assert p != travel.Params() and copy.deepcopy(p) == p
    assert pickle.loads(pickle.dumps(p)) == p
    assert travel.Params.from_yaml(p.to_yaml()) == p
    assert "ground_dist=0.2" in repr(p)
    assert travel.Params(ground_dist=0.2).ground_dist == 0.2


def test_params_errors_carry_the_library_messages():
    p = travel.Params()
    with pytest.raises(travel.ConfigError, match="outside its allowed range"):
        p.ground_dist = -1.0
    assert p.ground_dist == travel.Params().ground_dist  # unchanged on error
    with pytest.raises(ValueError, match="ground_dist"):
        p.ground_dist = float("nan")
    with pytest.raises(ValueError, match="not one of"):
        p.ring_source = "laser"
    with pytest.raises(ValueError, match="expected an int"):
        p.num_rings = 3.5
    with pytest.raises(ValueError, match="expected a bool"):
        p.deskew = 1
    with pytest.raises(ValueError, match="expected a number"):
        p.ground_dist = "0.2"
    with pytest.raises(ValueError, match="did you mean 'ground_dist'"):
        travel.Params(groun_dist=0.2)
    # Ints beyond any float or int parameter: ConfigError naming the key, not OverflowError.
    with pytest.raises(travel.ConfigError, match="ground_dist.*too large for a float"):
        travel.Params(ground_dist=10**400)
    with pytest.raises(travel.ConfigError, match="num_rings"):
        p.num_rings = 10**400
    with pytest.raises(AttributeError):
        p.no_such_parameter = 1
    p.min_range = 50.0
    p.max_range = 40.0
    with pytest.raises(travel.ConfigError, match="min_range"):
        p.validate()
    with pytest.raises(travel.ConfigError, match="min_range"):
        travel.Pipeline(p)
    with pytest.raises(travel.ConfigError, match="hdl64"):
        travel.Params.from_preset("no-such-sensor")


def test_presets_and_files(tmp_path):
    assert {"hdl64", "vlp16"} <= set(travel.Params.presets())
    vlp16 = travel.Params.from_preset("vlp16")
    assert vlp16.num_rings == 16
    config = tmp_path / "robot.yaml"
    config.write_text("travel:\n  preset: vlp16\n  sensor_height: 0.8\n")
    p = travel.Params.from_file(config)
    assert p.num_rings == 16 and p.sensor_height == 0.8
    config.write_text("travel:\n  sensor_hieght: 0.8\n")
    with pytest.raises(travel.ConfigError, match=r"robot.yaml:2:.*did you mean"):
        travel.Params.from_file(config)


def test_scan_and_label_files(tmp_path, frame):
    points = frame[0]
    path = tmp_path / "000000.bin"
    points.tofile(path)
    scan = travel.read_scan(path)
    assert scan.format == "kitti" and len(scan) == len(points) and scan.rings is None
    assert np.array_equal(scan.points, points)
    pipeline = travel.Pipeline(travel.Params())
    from_scan = pipeline.process(scan)
    assert np.array_equal(from_scan.labels, segment(points).labels)
    labels = tmp_path / "000000.label"
    travel.write_labels(labels, from_scan)
    encoded = travel.read_labels(labels)
    assert encoded.dtype == np.uint32 and len(encoded) == len(points)
    assert np.array_equal(encoded & 0xFFFF, from_scan.labels)
    assert np.array_equal(encoded >> 16, from_scan.cluster_ids)
    with pytest.raises(FileNotFoundError):
        travel.read_scan(tmp_path / "missing.bin")
    (tmp_path / "odd.bin").write_bytes(b"\0" * 13)
    with pytest.raises(travel.InputError, match="odd.bin"):
        travel.read_scan(tmp_path / "odd.bin")
    with pytest.raises(travel.ConfigError, match="pcd"):
        travel.read_scan(path, format="las")


def test_metrics(frame):
    points, _, is_box = frame
    r = segment(points)
    gt = np.where(is_box, (7 << 16) | 10, 40).astype(np.uint32)  # car instance 7, road
    gt[np.all(points[:, :3] == 0, axis=1)] = 0                 # no return: unlabeled
    gt[(points[:, 2] > -1.6) & ~is_box] = 0                     # the box's foot: unlabeled
    g = travel.metrics.ground(r, gt)
    assert g["f1"] > 95 and g["tp"] + g["fn"] == np.sum(gt == 40)
    a = travel.metrics.ground(r, gt, protocol="A", z=points[:, 2])
    assert a["f1"] > 95
    with pytest.raises(ValueError, match="protocol"):
        travel.metrics.ground(r, gt, protocol="C")
    with pytest.raises(ValueError, match="gt"):
        travel.metrics.ground(r, gt[:-1])
    o = travel.metrics.objects(r, gt, points)
    assert o["mean_coverage"] > 0.9 and o["mean_purity"] > 0.9 and len(o["instances"]) == 1


def test_threads_give_identical_results():
    frames = [synthetic_frame(seed=s)[0] for s in range(4)]
    serial = [segment(f) for f in frames]

    def run(index):  # one Pipeline per thread, several frames each
        pipeline = travel.Pipeline(travel.Params())
        return [pipeline.process(frames[(index + k) % 4]) for k in range(4)]

    with concurrent.futures.ThreadPoolExecutor(4) as pool:
        results = list(pool.map(run, range(4)))
    for index, rs in enumerate(results):
        for k, r in enumerate(rs):
            expected = serial[(index + k) % 4]
            assert np.array_equal(r.labels, expected.labels)
            assert np.array_equal(r.cluster_ids, expected.cluster_ids)
    # One Pipeline shared by threads: calls serialise, results stay whole.
    shared = travel.Pipeline(travel.Params())
    with concurrent.futures.ThreadPoolExecutor(4) as pool:
        rs = list(pool.map(lambda k: shared.process(frames[k % 4]), range(8)))
    for k, r in enumerate(rs):
        assert np.array_equal(r.labels, serial[k % 4].labels)


def test_float32_of_any_origin_is_accepted(frame):
    """A float32 array is float32 whatever dtype object describes it: an unpickled array (its
    dtype is a new, equal object) and a big-endian one give the labels of the native array."""
    points = frame[0]
    reference = segment(points)
    for name, p in {"unpickled": pickle.loads(pickle.dumps(points)),
                    "big-endian": points.astype(">f4"),
                    "big-endian float64": points.astype(">f8")}.items():
        assert np.array_equal(segment(p).labels, reference.labels), name
        h = reference.terrain.height_above_ground(p[:10])
        assert np.array_equal(h, reference.terrain.height_above_ground(points[:10]), equal_nan=True)
    # Every points argument reads what process reads, a list included.
    h = reference.terrain.height_above_ground([[5.0, 0.5, -1.0]])
    assert abs(h[0] - 0.73) < 0.05
    gt = np.full(len(points), 40)
    assert travel.metrics.objects(reference, gt, points[:, :3].tolist()) == \
        travel.metrics.objects(reference, gt, points)


def test_integers_out_of_range_are_refused_not_wrapped(tmp_path, frame):
    """Integer arrays are converted only when every value fits: a class 257 or -255 is not
    class 1, a cluster id -1 or 2**33 is not 65535 or 0 (no cluster), a gt label -1 is not
    0xFFFFFFFF."""
    path = tmp_path / "x.label"
    with pytest.raises(ValueError, match=r"labels: values must be in \[0, 3\]"):
        travel.write_labels(path, np.array([1, 257]), np.array([0, 0]))
    with pytest.raises(ValueError, match=r"labels: values must be in \[0, 3\]"):
        travel.write_labels(path, np.array([1, -255]), np.array([0, 0]))
    for bad in (-1, 2 ** 33):
        with pytest.raises(ValueError, match="cluster_ids: values must be in"):
            travel.write_labels(path, np.array([1, 2]), np.array([0, bad]))
    assert not path.exists()
    travel.write_labels(path, np.array([1, 2], np.int64), np.array([0, 2 ** 32 - 1], np.uint64))
    assert list(travel.read_labels(path)) == [1, (0xFFFF << 16) | 2]
    labels, gt = segment(frame[0]).labels, np.full(len(frame[0]), 40)
    for bad in (5, 257):
        with pytest.raises(ValueError, match=r"labels: values must be in \[0, 3\]"):
            travel.metrics.ground(np.full(len(gt), bad), gt)
    with pytest.raises(ValueError, match="gt: values must be in"):
        travel.metrics.ground(labels, np.full(len(gt), -1))
    with pytest.raises(ValueError, match=r"rings: values must be in \[0, 65535\]"):
        segment(frame[0], rings=np.full(len(gt), -1))


def test_params_compare_with_anything():
    """Params == something else is False (not a TypeError), so Params sit in lists and dicts."""
    p = travel.Params()
    assert not (p == 1) and p != None and p != "hdl64"  # noqa: E711
    assert p in [None, travel.Params()] and p not in [1, "x"]
    assert {"a": p} == {"a": travel.Params()}


def test_terrain_arrays_are_built_once(frame):
    """A terrain array is built on its first read and kept (docs/python.md): reading it in a loop
    costs nothing more, and the array read is the array kept."""
    t = segment(frame[0]).terrain
    for name in ("node_class", "num_points", "planes", "means", "weights", "reached",
                 "traversable", "ground_planes", "corners"):
        assert getattr(t, name) is getattr(t, name), name
    # Read-only: an edit would not reach the model that node_at / height_above_ground read.
    with pytest.raises(ValueError, match="read-only"):
        t.traversable[0] = not t.traversable[0]


def test_file_errors_are_os_errors(tmp_path, frame):
    """Every reader raises FileNotFoundError for a missing file and IsADirectoryError for a
    folder (both OSError, naming the path), and write_labels an OSError when it cannot write."""
    for read in (travel.read_scan, travel.read_labels):
        with pytest.raises(FileNotFoundError, match="missing.bin"):
            read(tmp_path / "missing.bin")
        with pytest.raises(IsADirectoryError, match=str(tmp_path)):
            read(tmp_path)
    r = segment(frame[0])
    with pytest.raises(OSError, match="no-such-folder"):
        travel.write_labels(tmp_path / "no-such-folder" / "x.label", r)


def test_every_path_argument_takes_str_bytes_and_pathlike(tmp_path, frame):
    config = tmp_path / "robot.yaml"
    config.write_text("travel:\n  num_rings: 32\n")
    scan_file = tmp_path / "000000.bin"
    frame[0].tofile(scan_file)
    for path in (config, str(config), bytes(config)):
        assert travel.Params.from_file(path).num_rings == 32, repr(path)
    for path in (scan_file, str(scan_file), bytes(scan_file)):
        r = segment(travel.read_scan(path))
        label_file = tmp_path / "x.label"
        travel.write_labels(bytes(label_file), r)
        assert np.array_equal(travel.read_labels(bytes(label_file)) & 0xFFFF, r.labels)


def test_numpy_scalars_are_their_python_types():
    """A numpy scalar sets a parameter as the Python number or bool it stands for (array.any()
    is a numpy bool); a bool is still no number."""
    p = travel.Params()
    p.deskew = np.bool_(False)
    p.num_rings = np.int32(32)
    p.ground_dist = np.float32(0.25)
    assert (p.deskew, p.num_rings, p.ground_dist) == (False, 32, float(np.float32(0.25)))
    assert travel.Params(deskew=np.zeros(3).any()).deskew is False
    for key in ("num_rings", "ground_dist"):
        with pytest.raises(travel.ConfigError, match="expected a"):
            setattr(p, key, np.True_)


def test_attitude_and_gravity_the_library_would_ignore_are_refused(frame):
    """The library does not use an attitude that is no rotation, nor a zero gravity (a stream
    goes on level); in Python such an argument is a mistake and raises instead of being
    silently ignored."""
    points = frame[0][:1000]
    pipeline = travel.Pipeline(travel.Params())
    for bad in (2 * np.eye(3), np.ones((3, 3)), np.diag([1.0, 1.0, -1.0])):
        with pytest.raises(ValueError, match="attitude.*not a rotation"):
            pipeline.process(points, attitude=bad)
    with pytest.raises(ValueError, match="gravity.*zero"):
        pipeline.process(points, gravity=[0, 0, 0])
    tilted = np.array([[1, 0, 0], [0, np.cos(0.1), -np.sin(0.1)], [0, np.sin(0.1), np.cos(0.1)]])
    pipeline.process(points, attitude=tilted, gravity=[0, 0, -9.81])


def test_cluster_ids_beside_a_result_are_not_ignored(tmp_path, frame):
    """write_labels and metrics.objects take a Result, or labels with cluster_ids: ids given
    beside a Result (which has its own) raise instead of being silently dropped."""
    points, _, is_box = frame
    r = segment(points)
    other = np.zeros(len(points), np.uint32)
    with pytest.raises(ValueError, match="cluster_ids"):
        travel.write_labels(tmp_path / "x.label", r, other)
    assert not (tmp_path / "x.label").exists()
    gt = np.where(is_box, (7 << 16) | 10, 40).astype(np.uint32)
    with pytest.raises(ValueError, match="cluster_ids"):
        travel.metrics.objects(r, gt, points, cluster_ids=other)
    travel.write_labels(tmp_path / "x.label", r.labels, other)  # the labels-array form
    assert np.array_equal(travel.read_labels(tmp_path / "x.label"), r.labels)
    assert travel.metrics.objects(r.labels, gt, points, cluster_ids=r.cluster_ids) == \
        travel.metrics.objects(r, gt, points)


def test_every_params_pickles():
    """A Params pickles and copies whatever it holds, also before validate() would pass (Params
    takes values one by one; rules between them are checked by validate() and Pipeline)."""
    p = travel.Params(min_range=50.0, max_range=40.0)
    for q in (pickle.loads(pickle.dumps(p)), copy.deepcopy(p), copy.copy(p)):
        assert q == p and (q.min_range, q.max_range) == (50.0, 40.0)
    with pytest.raises(travel.ConfigError, match="min_range"):
        pickle.loads(pickle.dumps(p)).validate()


# ---- Pickling ------------------------------------------------------------------------------

TERRAIN_METHODS = {  # every Terrain method, called the same way on both sides
    "node_at": lambda t, points: [t.node_at(x, y) for x, y in points[::97, :2]],
    "height_above_ground": lambda t, points: t.height_above_ground(points),
}


def assert_same(a, b, points, where="", skip=()):
    """a and b are equal bit for bit in everything they expose: arrays by dtype, shape and bytes,
    floats by their bits (NaN included), travel objects by every public attribute (a method
    without a call in TERRAIN_METHODS fails, so that a new one gets compared)."""
    assert type(a) is type(b), where
    if isinstance(a, np.ndarray):
        assert (a.dtype, a.shape) == (b.dtype, b.shape), where
        assert a.tobytes() == b.tobytes(), where
    elif isinstance(a, float):
        assert struct.pack("<d", a) == struct.pack("<d", b), where
    elif isinstance(a, dict):
        assert a.keys() == b.keys(), where
        for key in a:
            assert_same(a[key], b[key], points, f"{where}[{key!r}]")
    elif type(a).__module__ == "travel._travel":
        assert len(a) == len(b), where
        names = [n for n in dir(type(a)) if not n.startswith("_") and n not in skip]
        assert names, where
        for name in names:
            if isinstance(getattr(type(a), name), property):
                assert_same(getattr(a, name), getattr(b, name), points, f"{where}.{name}")
            else:
                assert name in TERRAIN_METHODS, f"{where}.{name}: no comparison for this method"
                assert_same(TERRAIN_METHODS[name](a, points), TERRAIN_METHODS[name](b, points),
                            points, f"{where}.{name}()")
    elif isinstance(a, list):
        assert len(a) == len(b), where
        for k, (x, y) in enumerate(zip(a, b)):
            assert_same(x, y, points, f"{where}[{k}]")
    else:
        assert a == b, where


def scan_file(tmp_path, seed=0):
    """A synthetic frame as a binary PCD with ring and time fields, read back as a travel.Scan."""
    points, ring, _ = synthetic_frame(seed=seed)
    fields = [("x", "<f4"), ("y", "<f4"), ("z", "<f4"), ("intensity", "<f4"), ("ring", "<u2"),
              ("time", "<f4")]
    records = np.zeros(len(points), dtype=fields)
    for k, name in enumerate(("x", "y", "z", "intensity")):
        records[name] = points[:, k]
    records["ring"] = ring
    records["time"] = np.linspace(0, 0.1, len(points), dtype=np.float32)
    header = (f"VERSION 0.7\nFIELDS x y z intensity ring time\nSIZE 4 4 4 4 2 4\n"
              f"TYPE F F F F U F\nCOUNT 1 1 1 1 1 1\nWIDTH {len(points)}\nHEIGHT 1\n"
              f"VIEWPOINT 0 0 0 1 0 0 0\nPOINTS {len(points)}\nDATA binary\n")
    path = tmp_path / f"{seed:06d}.pcd"
    path.write_bytes(header.encode() + records.tobytes())
    return travel.read_scan(path)


def test_results_scans_and_their_parts_pickle_exactly(tmp_path, frame):
    points = frame[0]
    # 'auto': the first frame's Result carries a mount note.
    r = travel.Pipeline(travel.Params(sensor_height="auto")).process(points)
    assert r.mount_note and len(r.clusters) > 0 and np.isnan(r.terrain.corners).any()
    kitti = tmp_path / "000000.bin"
    points.tofile(kitti)
    scans = [travel.read_scan(kitti), scan_file(tmp_path)]
    assert scans[0].rings is None and scans[1].rings is not None and scans[1].times is not None
    for obj in (r, r.clusters, r.terrain, *scans):
        for protocol in (2, pickle.HIGHEST_PROTOCOL):
            assert_same(obj, pickle.loads(pickle.dumps(obj, protocol)), points, repr(obj))
        assert_same(obj, copy.deepcopy(obj), points, repr(obj))
    # An unpickled Result's clusters and terrain are its own (as from process()); a part
    # pickled apart from its Result holds its own data.
    r2, terrain2 = pickle.loads(pickle.dumps((r, r.terrain)))
    assert r2.terrain is r2.terrain and terrain2 is not r2.terrain
    del r2
    assert_same(terrain2, r.terrain, points)
    # Writable arrays pickle as edited (the caller's own ids), like any numpy array.
    r.cluster_ids[:] = 7
    r.clusters.ids[:] = 70000
    assert_same(pickle.loads(pickle.dumps(r)), r, points)
    # A shallow copy holds arrays of its own, writable: editing them leaves the original.
    shallow = copy.copy(r)
    assert_same(shallow, r, points)
    shallow.labels[:] = 0
    shallow.cluster_ids[:] = 1
    shallow.clusters.ids[:] = 2
    assert (r.cluster_ids == 7).all() and (r.clusters.ids == 70000).all()
    assert not (r.labels == 0).all()
    # Out-of-band buffers (protocol 5) are read-only; the unpickled arrays are not.
    buffers = []
    data = pickle.dumps(r, protocol=5, buffer_callback=buffers.append)
    oob = pickle.loads(data, buffers=[memoryview(b.raw()).toreadonly() for b in buffers])
    assert oob.labels.flags.writeable and oob.clusters.ids.flags.writeable
    assert_same(oob, r, points)
    # A Result of no points, no clusters.
    empty = segment(np.zeros((0, 3), np.float32))
    assert len(empty) == 0 and len(empty.clusters) == 0
    assert_same(pickle.loads(pickle.dumps(empty)), empty, points)


def _process(params, points):
    return travel.Pipeline(params).process(points)


def test_a_process_pool_gives_the_in_process_results(tmp_path):
    """Scans and Params go to worker processes, Results come back: equal to the in-process
    ones in everything but the timings (CPU time of the worker)."""
    params = travel.Params.from_preset("hdl64")
    jobs = [(params, scan_file(tmp_path, seed)) for seed in range(2)]
    jobs += [(params, synthetic_frame(seed=seed)[0]) for seed in range(2, 4)]
    with multiprocessing.get_context("spawn").Pool(2) as pool:
        results = pool.starmap(_process, jobs)
    for (p, points), result in zip(jobs, results):
        expected = _process(p, points)
        array = points if isinstance(points, np.ndarray) else points.points
        assert_same(result, expected, array, skip=("timings",))
        assert result.timings.keys() == expected.timings.keys()


def _new(cls):
    return cls.__new__(cls)


class _Forged:
    """Pickles as `cls` with `state`, as a corrupt file or another version would (unpickled
    as copyreg.__newobj__ would: cls.__new__(cls), then __setstate__(state))."""

    def __init__(self, cls, state):
        self.cls, self.state = cls, state

    def __reduce__(self):
        return _new, (self.cls,), self.state


def unpickle(cls, state):
    return pickle.loads(pickle.dumps(_Forged(cls, state)))


def test_a_bad_state_raises_value_error_naming_the_item(tmp_path, frame):
    r = segment(frame[0])
    state = r.__reduce_ex__(2)[2]
    assert_same(unpickle(travel.Result, state), r, frame[0])

    def with_item(s, k, value):
        return s[:k] + (value,) + s[k + 1:]

    clusters, terrain = state[2], state[3]
    node_class = terrain[5].copy()
    node_class[0] = 9
    bad = {
        "expected a tuple of 8 items, got list": list(state),
        "expected a tuple of 8 items, got 7": state[:-1],
        r"labels: expected a uint8 array of shape \(N,\), got int64 of shape":
            with_item(state, 0, state[0].astype(np.int64)),
        rf"cluster_ids: expected a uint32 array of shape \({len(r)},\), got uint32 of shape":
            with_item(state, 1, state[1][:-1]),
        rf"clusters: centroids: expected a float32 array of shape \({len(r.clusters)}, 3\)":
            with_item(state, 2, with_item(clusters, 3, clusters[3][:, :2])),
        r"terrain: cells_per_side: expected an int in \[0, 23170\], got -1":
            with_item(state, 3, with_item(terrain, 1, -1)),
        "terrain: resolution: expected a float, got str":
            with_item(state, 3, with_item(terrain, 0, "0.5")),
        rf"terrain: weights: expected a float32 array of shape \({len(r.terrain)},\), got float64":
            with_item(state, 3, with_item(terrain, 9, terrain[9].astype(np.float64))),
        r"terrain: node_class: values must be in \[0, 3\], got 9":
            with_item(state, 3, with_item(terrain, 5, node_class)),
        "timings: expected a tuple of 12 items, got 11": with_item(state, 4, state[4][1:]),
        rf"class_counts: ground: expected an int in \[0, {len(r)}\], got str":
            with_item(state, 5, with_item(state[5], 1, "many")),
        "mount_note: expected a str, got bytes": with_item(state, 7, b""),
    }
    for message, s in bad.items():
        with pytest.raises(ValueError, match="cannot unpickle travel.Result: " + message):
            unpickle(travel.Result, s)
    with pytest.raises(ValueError, match=r"travel.Terrain: seed_node: expected an int in \["):
        unpickle(travel.Terrain, with_item(terrain, 3, 10**30))
    with pytest.raises(ValueError, match="travel.Clusters: expected a tuple of 11 items"):
        unpickle(travel.Clusters, clusters + clusters)
    frame[0].tofile(tmp_path / "0.bin")
    scan = travel.read_scan(tmp_path / "0.bin").__reduce_ex__(2)[2]
    for message, s in {
        r"points: expected a float32 array of shape \(N, 4\), got float32 of shape \(\d+, 3\)":
            with_item(scan, 2, scan[2][:, :3]),
        r"rings: expected a uint16 array of shape \(\d+,\), got int32":
            with_item(scan, 3, np.zeros(len(scan[2]), np.int32)),
        "format: unknown scan format 'las'": with_item(scan, 1, "las"),
    }.items():
        with pytest.raises(ValueError, match="cannot unpickle travel.Scan: " + message):
            unpickle(travel.Scan, s)
    # An array of the other byte order, or a strided view, holds the same values.
    swapped = with_item(state, 1, np.repeat(state[1].astype(">u4"), 2)[::2])
    assert_same(unpickle(travel.Result, swapped), r, frame[0])
