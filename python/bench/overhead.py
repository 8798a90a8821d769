#!/usr/bin/env python3
"""Overhead of the Python binding over the C++ call Pipeline::process on one scan.

    PYTHONPATH=build/python /usr/bin/python3 python/bench/overhead.py SCAN.bin [--rounds 15]

Each round times `--calls` consecutive frames three ways, interleaved so that load changes on the
machine hit all three alike: the C++ loop (travel._bench_cpp: Pipeline::process on the library's
cloud, no Python inside), pipeline.process(numpy (N, 4) float32) and pipeline.process(Scan).
Prints the median milliseconds per call of each and the overhead of the medians. Run it on an
idle machine; it asserts nothing.
"""
import argparse
import statistics
import time


import travel

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("scan", help="an HDL-64E scan, e.g. a KITTI velodyne/000000.bin")
parser.add_argument("--preset", default="hdl64")
parser.add_argument("--rounds", type=int, default=15)
parser.add_argument("--calls", type=int, default=10, help="frames per round and way")
args = parser.parse_args()

params = travel.Params.from_preset(args.preset)
scan = travel.read_scan(args.scan)
points = scan.points  # (N, 4) float32, C order: what a numpy user holds
pipeline = travel.Pipeline(params)


def python_ms(inputs):
    out = []
    for _ in range(args.calls):
        start = time.perf_counter()
        result = pipeline.process(inputs)
        out.append((time.perf_counter() - start) * 1e3)
        del result
    return out


for _ in range(3):  # warm up caches, allocations and the mount check of the first frame
    pipeline.process(points)
travel._travel._bench_cpp(params, scan, 3)
cpp, numpy_in, scan_in = [], [], []
for _ in range(args.rounds):
    cpp += travel._travel._bench_cpp(params, scan, args.calls)
    numpy_in += python_ms(points)
    scan_in += python_ms(scan)

base = statistics.median(cpp)
print(f"{len(scan)} points, preset {args.preset}, {args.rounds} rounds x {args.calls} calls")
print(f"C++ Pipeline::process          median {base:7.3f} ms")
for name, series in (("Python process(numpy (N, 4))", numpy_in), ("Python process(Scan)", scan_in)):
    m = statistics.median(series)
    print(f"{name:30s} median {m:7.3f} ms  overhead {m - base:+6.3f} ms "
          f"= {100 * (m / base - 1):+5.1f} %")
