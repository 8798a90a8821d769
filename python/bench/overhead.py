#!/usr/bin/env python3
"""Overhead of the Python binding over the C++ call Pipeline::process on one scan.

    PYTHONPATH=build/python /usr/bin/python3 python/bench/overhead.py SCAN.bin [--calls 300]

One Pipeline, warmed up, segments the same scan three ways in turn, call after call, so that load
changes on the machine hit all three alike: the C++ call (travel._travel._bench_cpp:
Pipeline::process on the library's cloud and result buffers, no Python inside), Python
pipeline.process(numpy (N, 4) float32) and pipeline.process(Scan). Prints the median
milliseconds of each and the median of the per-call differences to the C++ call. Run it on an
idle machine; it asserts nothing.
"""
import argparse
import statistics
import time

import travel
from travel import _travel

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("scan", help="an HDL-64E scan, e.g. a KITTI velodyne/000000.bin")
parser.add_argument("--preset", default="hdl64")
parser.add_argument("--calls", type=int, default=300, help="calls of each way")
args = parser.parse_args()

scan = travel.read_scan(args.scan)
points = scan.points  # (N, 4) float32, C order: what a numpy user holds
pipeline = travel.Pipeline(travel.Params.from_preset(args.preset))


def python_ms(inputs):
    start = time.perf_counter()
    pipeline.process(inputs)
    return (time.perf_counter() - start) * 1e3


for _ in range(5):  # warm up: caches, allocations, the mount check of the first frame
    python_ms(points), python_ms(scan)
cpp, numpy_in, scan_in = [], [], []
for _ in range(args.calls):
    cpp += _travel._bench_cpp(pipeline, scan, 1)
    numpy_in.append(python_ms(points))
    scan_in.append(python_ms(scan))

base = statistics.median(cpp)
print(f"{len(scan)} points, preset {args.preset}, {args.calls} calls of each way")
print(f"C++ Pipeline::process          median {base:7.3f} ms")
for name, series in (("Python process(numpy (N, 4))", numpy_in), ("Python process(Scan)", scan_in)):
    diff = statistics.median(p - c for p, c in zip(series, cpp))
    print(f"{name:30s} median {statistics.median(series):7.3f} ms, per call "
          f"{diff:+6.3f} ms = {100 * diff / base:+5.1f} %")
