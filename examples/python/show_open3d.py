#!/usr/bin/env python3
"""Show a segmented scan in Open3D, coloured by class or by cluster.

    python3 examples/python/show_open3d.py velodyne/000000.bin              # a window
    python3 examples/python/show_open3d.py scan.bin --color cluster --save out.ply  # headless

Classes: ground green, non-ground grey, outlier blue, invalid (not shown) black. Clusters: each
its own colour, ground green, the rest grey. With --save no window is opened.
"""
import argparse
import sys

import numpy as np
import open3d as o3d

import travel

CLASS_COLOURS = np.array([[0, 0, 0], [0.1, 0.7, 0.2], [0.6, 0.6, 0.6], [0.2, 0.3, 0.9]])


def colours(result, by):
    rgb = CLASS_COLOURS[result.labels]
    if by == "cluster":
        palette = np.random.default_rng(1).uniform(0.2, 1.0, (len(result.clusters) + 1, 3))
        clustered = result.cluster_ids > 0
        rgb[clustered] = palette[result.cluster_ids[clustered]]
    return rgb


parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("scan")
parser.add_argument("-p", "--preset", default="hdl64")
parser.add_argument("--color", choices=("class", "cluster"), default="class")
parser.add_argument("--save", metavar="FILE", help="write a coloured .ply / .pcd instead of a window")
args = parser.parse_args()

scan = travel.read_scan(args.scan)
result = travel.Pipeline(travel.Params.from_preset(args.preset)).process(scan)
shown = result.labels != travel.INVALID
cloud = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(scan.points[shown, :3].astype(np.float64)))
cloud.colors = o3d.utility.Vector3dVector(colours(result, args.color)[shown])
# Cluster boxes are in the aligned frame: the sensor frame for a level, unrotated mount.
boxes = [o3d.geometry.AxisAlignedBoundingBox(lo, hi)
         for lo, hi in zip(result.clusters.aabb_min.astype(np.float64),
                           result.clusters.aabb_max.astype(np.float64))]
print(f"{shown.sum()} points, {len(result.clusters)} clusters, colour by {args.color}")
if args.save:
    if not o3d.io.write_point_cloud(args.save, cloud):  # Open3D only warns; say it and fail
        sys.exit(f"error: could not write {args.save} (folder missing? extension not .ply/.pcd?)")
    print(f"written to {args.save}")
else:
    o3d.visualization.draw_geometries([cloud, *boxes], window_name=f"TRAVEL: {args.scan}")
