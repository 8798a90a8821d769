// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// One reader for every scan file format: readScan(path, cloud, format). Formats:
//   kitti     KITTI .bin, float32 records x, y, z, intensity (16 bytes)
//   nuscenes  nuScenes .bin (*.pcd.bin), float32 records x, y, z, intensity, ring (20 bytes)
//   pcd       PCL's PCD v0.7: DATA ascii, binary or binary_compressed (LZF)
//   ply       PLY: ascii or binary_little_endian, "vertex" element
// `auto` never guesses silently: see detectScanFormat(). Every malformed, empty or non-finite
// file is an InputError naming the file (and the header line where there is one), never an
// empty or junk cloud.
//
// Fields: x, y, z (required), intensity (0 when absent), ring (cloud.ring, empty when absent)
// and time (cloud.time [s], empty when absent). In PCD and PLY the time field is `time` or `t`;
// an integer-typed `t` is taken as nanoseconds (Ouster's driver), a floating one as seconds.
// Any other field is skipped.
//
// No third-party library: PCD and PLY headers are a few keywords, and the only compressed
// encoding (binary_compressed) is LZF, whose decoder is ~40 lines (src/Lzf.cpp). Debian's
// liblzf-dev would be one more dependency for users of an otherwise Eigen-only library, and
// PCL (the reference PCD reader) is far too heavy for that.
#pragma once

#include <string>

#include "travel/PointCloud.hpp"

namespace travel {

enum class ScanFormat { Auto, KittiBin, NuScenesBin, Pcd, Ply };

/// "auto", "kitti", "nuscenes", "pcd", "ply" (the names --format takes).
const char* toString(ScanFormat format);

/// The names above, comma-separated, for help texts and messages.
const char* scanFormatNames();

/// Parses a --format value (case-sensitive). Throws ConfigError listing the allowed names.
ScanFormat scanFormatFromString(const std::string& name);

/// The format of the file at `path`, decided without guessing:
///  - a PCD or PLY file by its extension (.pcd, .ply) or its first line;
///  - a .bin file by its name or folder: nuScenes for "*__LIDAR_TOP__*" names and
///    samples/LIDAR_TOP or sweeps/LIDAR_TOP folders, KITTI for a "velodyne" folder;
///  - otherwise a .bin file by its size (a multiple of 16 bytes: KITTI, of 20: nuScenes) and,
///    when that is not conclusive, by which decoding gives plausible points (nuScenes: every
///    5th float an integer ring in [0, 255]; both: intensity finite in [0, 65535], coordinates
///    finite and under 1 km, for at least 99 % of the points with finite coordinates).
/// Throws InputError naming the file and `--format` when it cannot tell, or when the file is
/// missing, empty or of a size neither layout allows.
ScanFormat detectScanFormat(const std::string& path);

/// Reads the scan at `path` into `cloud`, reusing its vectors' capacity. x, y, z and intensity
/// always have one value per point (intensity 0 when the file has none); ring and time are
/// filled when the file has them and cleared otherwise. Throws InputError naming the file.
/// An explicit `format` is trusted (no plausibility check), but the file must still be well
/// formed, non-empty, and hold at least one point with finite x, y, z. Returns the format read
/// (`format`, or the one detectScanFormat() finds for Auto: the file is read once).
ScanFormat readScan(const std::string& path, PointCloud& cloud,
                    ScanFormat format = ScanFormat::Auto);

/// Writes `cloud` as a KITTI .bin (a missing intensity is written as 0). Throws
/// std::invalid_argument if x, y, z (or a non-empty intensity) differ in size.
void writeKittiBin(const std::string& path, const PointCloud& cloud);

enum class PcdEncoding { Ascii, Binary, BinaryCompressed };

/// Writes `cloud` as PCD v0.7: FIELDS x y z intensity (F4), plus ring (U2) and time (F4 [s])
/// when the cloud has them. Same size checks as writeKittiBin().
void writePcd(const std::string& path, const PointCloud& cloud, PcdEncoding encoding);

enum class PlyEncoding { Ascii, BinaryLittleEndian };

/// Writes `cloud` as a PLY "vertex" element with the same properties as writePcd().
void writePly(const std::string& path, const PointCloud& cloud, PlyEncoding encoding);

}  // namespace travel
