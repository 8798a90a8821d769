#!/usr/bin/env python3
"""Ground F1 (protocol B) and object coverage of a SemanticKITTI sequence, in ten lines.

    python3 examples/python/evaluate_folder.py data/sequences/00
"""
import pathlib, sys, numpy as np, travel

seq = pathlib.Path(sys.argv[1])
pipeline, f1, coverage = travel.Pipeline(travel.Params.from_preset("hdl64")), [], []
for label_file in sorted((seq / "labels").glob("*.label")):
    scan = travel.read_scan(seq / "velodyne" / (label_file.stem + ".bin"))
    result, gt = pipeline.process(scan), travel.read_labels(label_file)
    f1.append(travel.metrics.ground(result, gt, protocol="B")["f1"])
    coverage.append(travel.metrics.objects(result, gt, scan.points)["mean_coverage"])
print(f"{len(f1)} frames: ground F1 {np.mean(f1):.2f} %, object coverage {np.mean(coverage):.3f}")
