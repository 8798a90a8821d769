"""TRAVEL for MRPT: traversable ground and above-ground object segmentation of LiDAR scans.

    import travel
    scan = travel.read_scan("000000.bin")                       # KITTI/nuScenes .bin, PCD, PLY
    result = travel.Pipeline(travel.Params.from_preset("hdl64")).process(scan.points)
    print(result.class_counts, len(result.clusters))
    travel.write_labels("000000.label", result)                 # travel-kitti's .label format

A thin binding of libtravel (C++): every rule (parameters, readers, labels, metrics) is the
library's. Classes per point: INVALID 0, GROUND 1, NONGROUND 2, OUTLIER 3. See docs/python.md.
"""
import errno as _errno
import os as _os

from ._travel import (  # noqa: F401
    Clusters,
    ConfigError,
    InputError,
    Params,
    Pipeline,
    Result,
    Scan,
    Terrain,
)
from ._travel import read_labels as _read_labels
from ._travel import read_scan as _read_scan
from . import metrics  # noqa: F401

INVALID, GROUND, NONGROUND, OUTLIER = 0, 1, 2, 3
CLASS_NAMES = ("invalid", "ground", "nonground", "outlier")

__all__ = [
    "Clusters", "ConfigError", "InputError", "Params", "Pipeline", "Result", "Scan", "Terrain",
    "read_scan", "read_labels", "write_labels", "metrics",
    "INVALID", "GROUND", "NONGROUND", "OUTLIER", "CLASS_NAMES",
]


def _input_file(path, what):
    """`path` as a str when it names a file; else FileNotFoundError or IsADirectoryError (both
    OSError) naming it, as open() would raise them."""
    path = _os.fspath(path)
    if isinstance(path, bytes):
        path = _os.fsdecode(path)
    if _os.path.isdir(path):
        raise IsADirectoryError(_errno.EISDIR, f"Is a directory, not a {what} file", path)
    if not _os.path.isfile(path):
        raise FileNotFoundError(_errno.ENOENT, f"No such {what} file", path)
    return path


def read_scan(path, format="auto"):
    """Reads a scan with the library's reader: format "auto", "kitti", "nuscenes", "pcd", "ply".

    Returns a travel.Scan (len(), .points (N, 4) float32, .rings, .times, .format); pass it to
    Pipeline.process as is (no copy). Raises FileNotFoundError for a missing file,
    IsADirectoryError for a folder and InputError (a ValueError) naming the file when it is
    malformed.
    """
    return _read_scan(_input_file(path, "scan"), format)


def read_labels(path):
    """A .label file (SemanticKITTI ground truth or travel-kitti output) as an (N,) uint32 array:
    the class in the lower 16 bits (label & 0xFFFF), the instance / cluster id in the upper 16
    (label >> 16). Raises FileNotFoundError for a missing file, IsADirectoryError for a folder
    and InputError naming the file when its size is not a multiple of 4."""
    return _read_labels(_input_file(path, "label"))


def write_labels(path, result, cluster_ids=None):
    """Writes a .label file as travel-kitti does: one little-endian uint32 per point, the class
    in the lower 16 bits, the cluster id in the upper 16 bits (ids above 65535 wrap to 1..65535).

    `result` is a travel.Result, or an (N,) class array with `cluster_ids` given (cluster_ids
    beside a Result raise ValueError: pass result.labels to write other ids). Raises OSError
    naming the file when it cannot be written.
    """
    labels, cluster_ids = metrics._classes_and_ids(result, cluster_ids, "write_labels")
    from ._travel import _write_labels
    _write_labels(_os.fspath(path), labels, cluster_ids)
