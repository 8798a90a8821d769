// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Which scans an input path names, for every app that reads scans (-i/--input): a single scan
// file, a folder of scans, or a KITTI / SemanticKITTI sequence folder (velodyne/ with the scans,
// labels/ with the ground truth, calib.txt and poses.txt beside them). One rule, here, instead
// of one per app.
#pragma once

#include <string>
#include <vector>

#include "travel/io/ScanIO.hpp"

namespace travel {

/// Throws InputError naming `dir` as `what` ("labels directory 'x' does not exist", "... is not
/// a directory") unless it is a directory.
void requireDirectory(const std::string& dir, const std::string& what);

/// Regular files in `dir` whose extension is `extension` ("bin" or ".bin"; empty = all), as
/// full paths sorted by name (KITTI names are zero-padded, so this is frame order). Throws
/// InputError if `dir` is not a directory.
std::vector<std::string> listFiles(const std::string& dir, const std::string& extension);

/// The extension of `path` in lower case (".bin" for "000000.BIN"): file kinds are told by their
/// extension case-insensitively.
std::string lowerCaseExtension(const std::string& path);

/// Whether `path` is named as a scan `format` reads, by its extension (case-insensitive): .bin
/// for kitti / nuscenes, .pcd, .ply, and all three for auto. The one extension rule of scan
/// inputs (listScans uses it for the files of a folder).
bool isScanPath(const std::string& path, ScanFormat format = ScanFormat::Auto);

struct ScanList {
    std::vector<std::string> files;  ///< the scans, in frame (name) order
    std::string scans_dir;           ///< the folder holding them
    std::string labels_dir;          ///< SemanticKITTI labels/ of the sequence, "" when none
    std::string sequence_dir;        ///< the KITTI sequence folder (calib.txt, poses.txt), or ""
};

/// The scans `path` names, in order:
///  - a scan file: that file alone;
///  - a folder with a velodyne/ subfolder (a KITTI sequence): the scans in velodyne/;
///  - any other folder: the scan files in it.
/// Scan files are those isScanPath(file, format) accepts. When the scans are in a folder named
/// velodyne whose parent has a labels/ folder, that is the labels folder. Throws InputError
/// naming `path` when it does not exist or holds no scan, and when two scans of a folder share
/// a stem (000000.bin and 000000.pcd: outputs are named by stem), suggesting --format.
ScanList listScans(const std::string& path, ScanFormat format = ScanFormat::Auto);

}  // namespace travel
