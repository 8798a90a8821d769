// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Robot/sensor trajectories from text files (Eigen only, no MRPT):
//   TUM     one pose per line: "timestamp x y z qx qy qz qw" (seconds, metres, unit quaternion);
//           '#' starts a comment; timestamps strictly increasing.
//   KITTI   one pose per frame: 12 numbers, the row-major 3x4 matrix [R | t] of the left camera
//           (cam0) in the world of the first frame (odometry benchmark poses/XX.txt).
//   calib   KITTI odometry calib.txt: the line "Tr: r11 r12 r13 tx ... " (12 numbers) maps
//           LiDAR (velodyne) coordinates into cam0 coordinates.
// Errors are std::runtime_error "<file>:<line>: <what was expected>".
#pragma once

#include <Eigen/Geometry>

#include <optional>
#include <string>
#include <vector>

namespace travel {

struct PoseTrajectory {
    std::vector<double> times;  ///< [s] TUM only (empty for KITTI: poses are per frame)
    std::vector<Eigen::Isometry3d, Eigen::aligned_allocator<Eigen::Isometry3d>> poses;

    std::size_t size() const { return poses.size(); }
    bool timed() const { return !times.empty(); }
};

PoseTrajectory readTumPoses(const std::string& path);
PoseTrajectory readKittiPoses(const std::string& path);
/// Reads whichever of the two the file holds (8 columns: TUM, 12: KITTI, judged on the first
/// data line).
PoseTrajectory readPoseFile(const std::string& path);
/// The Tr (velodyne -> cam0) transform of a KITTI calib.txt.
Eigen::Isometry3d readKittiCalibTr(const std::string& path);
/// KITTI cam0 poses -> LiDAR poses in the first LiDAR frame: Tr^-1 * P_k * Tr.
void kittiCameraToLidar(PoseTrajectory& trajectory, const Eigen::Isometry3d& tr);

/// The LiDAR poses of a KITTI sequence folder (travel::ScanList::sequence_dir): its poses.txt
/// (cam0) moved into the LiDAR frame with its calib.txt when there is one (else taken as LiDAR
/// poses). Nothing when the folder has no poses.txt.
std::optional<PoseTrajectory> readSequenceLidarPoses(const std::string& sequence_dir);

/// One line of a KITTI pose file: the row-major 3x4 [R | t], 12 numbers ("%.9e"), '\n'.
std::string kittiPoseLine(const Eigen::Isometry3d& pose);

/// Pose at time t: linear / slerp interpolation between the bracketing poses; nothing when t
/// is outside [first - tolerance, last + tolerance] or the bracketing poses are more than
/// max_gap seconds apart.
std::optional<Eigen::Isometry3d> poseAt(const PoseTrajectory& trajectory, double t,
                                        double tolerance = 0.05, double max_gap = 1.0);

}  // namespace travel
