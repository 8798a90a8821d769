#!/usr/bin/env python3
"""Segment one scan and save its labels in travel-kitti's .label format.

    python3 examples/python/segment_scan.py velodyne/000000.bin -o 000000.label [--preset hdl64]
"""
import argparse

import travel

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("scan", help="KITTI / nuScenes .bin, .pcd or .ply")
parser.add_argument("-o", "--output", help=".label file to write (default: print only)")
parser.add_argument("-p", "--preset", default="hdl64", help="sensor preset (default hdl64)")
args = parser.parse_args()

scan = travel.read_scan(args.scan)                      # the library's reader, as the apps
pipeline = travel.Pipeline(travel.Params.from_preset(args.preset))
result = pipeline.process(scan)                         # a Scan goes in without a copy
counts = result.class_counts
print(f"{len(scan)} points: ground {counts['ground']}, non-ground {counts['nonground']}, "
      f"outlier {counts['outlier']}, invalid {counts['invalid']}; "
      f"{len(result.clusters)} clusters; {result.timings['total']:.1f} ms")
if result.mount_note:
    print(result.mount_note)
if args.output:
    travel.write_labels(args.output, result)            # class | cluster id << 16, as travel-kitti
    print(f"labels written to {args.output}")
