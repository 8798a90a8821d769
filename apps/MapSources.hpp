// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// travel-map's inputs: an MRPT rawlog (through travel_mrpt::RawlogReader / RawlogMotion) or a
// KITTI sequence, fed frame by frame at its robot pose into a CTraversabilityMap.
#pragma once

#include <mrpt/poses/CPose3D.h>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "MemoryLimit.hpp"
#include "Progress.hpp"
#include "travel/io/ScanIO.hpp"
#include "travel/io/ScanList.hpp"
#include "travel/traversability/PoseFiles.hpp"
#include "travel_mrpt/CTraversabilityMap.hpp"

namespace travel::apps {

struct Options {
    std::string input, output_dir, poses, calib;
    std::string extent;
    std::optional<double> resolution;  ///< --resolution, when given
    long max_frames = 0;
    travel::ScanFormat format = travel::ScanFormat::Auto;  // -f, for scan folders
    Verbosity verbosity = Verbosity::Normal;
    /// -j: with >= 2, scans are read, segmented and fused into the grid on one thread while
    /// the calling thread updates the OctoMap with the previous ones (the map is the same).
    unsigned jobs = 1;
    std::size_t max_memory_mib = travel::apps::kDefaultMemoryLimitMiB;
};

/// Wall-clock times of one mapped frame [ms].
struct FrameTimes {
    double read_ms = 0;  ///< reading the scan file / the rawlog records up to the observation
    travel_mrpt::CTraversabilityMap::InsertTimes map;  ///< convert, segment, grid, OctoMap
    /// From the end of the previous frame's fusion to the end of this one's: the time a frame
    /// costs the whole program (with -j 2 the stages of consecutive frames overlap).
    double interval_ms = 0;
    /// CPU time [ms] of the thread that read, segmented and fused the frame into the grid, and
    /// of the one that updated the OctoMap (scan folders only; 0 for rawlogs).
    double cpu_ms[2] = {0, 0};
};

struct Stats {
    std::size_t records = 0, lidar = 0, inserted = 0, rejected = 0, no_pose = 0;
    std::string pose_source;
    /// Per mapped frame (for the summary's medians).
    std::vector<FrameTimes> times;
};

/// Poses for LiDAR frames from a pose file: TUM by timestamp, KITTI by LiDAR frame index.
struct PoseFileSource {
    travel::PoseTrajectory trajectory;
    std::optional<mrpt::poses::CPose3D> at(double t, std::size_t frame) const;
};

/// Maps every LiDAR observation of the rawlog o.input; `notes` (listening to the map's filter)
/// print above its progress line.
void mapRawlog(const Options& o, travel_mrpt::CTraversabilityMap& map, Stats& stats,
               const std::optional<PoseFileSource>& pose_file, Notes& notes);

/// The folder whose poses.txt and calib.txt go with `scans` (travel::listScans(input)): the
/// KITTI sequence folder, also when `input` is its velodyne/ folder, else `input` itself.
std::filesystem::path sequenceFolder(const travel::ScanList& scans, const std::string& input);

/// Maps `scans`, those of o.input (a KITTI sequence folder or a folder of scans); `notes` as for
/// mapRawlog.
void mapKitti(const Options& o, const travel::ScanList& scans, travel_mrpt::CTraversabilityMap& map,
              Stats& stats, std::optional<PoseFileSource> pose_file, Notes& notes);

}  // namespace travel::apps
