"""Scores against SemanticKITTI labels, computed by libtravel's evaluation code (the numbers
travel-kitti and travel-eval print). Ground classes: 40 road, 44 parking, 48 sidewalk,
49 other-ground, 60 lane-marking, 72 terrain.

    gt = travel.read_labels("labels/000000.label")
    travel.metrics.ground(result, gt)                      # protocol B (Patchwork++)
    travel.metrics.ground(result, gt, protocol="A", z=scan.points[:, 2])
    travel.metrics.objects(result, gt, scan.points)
"""
from . import _travel


def _labels_of(result):
    if isinstance(result, _travel.Result):
        return result.labels, result.sensor_height
    return result, None


def _classes_and_ids(result, cluster_ids, caller):
    """(labels, cluster_ids) of a Result, or of a labels array with its cluster_ids: `caller`'s
    two forms. Ids given beside a Result (which has its own) are an error, not dropped."""
    if isinstance(result, _travel.Result):
        if cluster_ids is not None:
            raise ValueError(f"{caller}: cluster_ids are given with a labels array; a Result has "
                             "its own (pass result.labels to use other cluster_ids)")
        return result.labels, result.cluster_ids
    if cluster_ids is None:
        raise ValueError(f"{caller}: give a Result, or labels and cluster_ids")
    return result, cluster_ids


def ground(labels, gt, protocol="B", z=None, sensor_height=None):
    """Ground precision / recall / F1 / accuracy in percent (never NaN) and the counts.

    labels: a travel.Result or an (N,) class array (only GROUND counts as predicted ground).
    gt: (N,) SemanticKITTI labels (semantic class = label & 0xFFFF).
    protocol "B" (Patchwork++): classes 0, 1 and 70 (vegetation) are not scored.
    protocol "A" (Patchwork benchmark): vegetation below -0.75 * sensor_height is ground; needs
    z (N,) the points' heights in the sensor frame, and sensor_height (taken from a Result).
    Returns {"precision", "recall", "f1", "accuracy", "tp", "fp", "tn", "fn"}.
    """
    labels, height = _labels_of(labels)
    if sensor_height is None:
        sensor_height = height
    if protocol == "A" and sensor_height is None:
        raise ValueError("protocol A needs sensor_height (or a Result)")
    return _travel._ground_metrics(labels, gt, z, float(sensor_height or 0.0), protocol)


def objects(result, gt, points, cluster_ids=None, gt_cluster_distance=0.5,
            min_gt_object_points=10, min_instance_points=50,
            entropy_on_predicted_nonground=True):
    """Object scores of one frame (libtravel/eval/include/travel/eval/ObjectMetrics.hpp):
    over- / under-segmentation entropy (paper eqs. 6-7) and instance coverage / purity.

    result: a travel.Result, or an (N,) class array with cluster_ids (N,) given (not both).
    gt: (N,) SemanticKITTI labels (instance id = label >> 16). points: (N, 3+) as segmented.
    Returns a dict: ose_sum, use_sum, ose_mean, use_mean, gt_objects, clusters, scored_points,
    mean_coverage, mean_purity, clustered, split, merged, instances (list of dicts).
    """
    labels, cluster_ids = _classes_and_ids(result, cluster_ids, "objects")
    if isinstance(points, _travel.Scan):
        points = points.points
    options = _travel._ObjectEvalOptions()
    options.gt_cluster_distance = gt_cluster_distance
    options.min_gt_object_points = min_gt_object_points
    options.min_instance_points = min_instance_points
    options.entropy_on_predicted_nonground = entropy_on_predicted_nonground
    return _travel._object_metrics(cluster_ids, labels, gt, points, options)
