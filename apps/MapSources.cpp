// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "MapSources.hpp"

#include <mrpt/maps/CPointsMapXYZI.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "Interrupt.hpp"
#include "Progress.hpp"
#include "travel/eval/KittiIO.hpp"
#include "travel_mrpt/ObservationAdapters.hpp"
#include "travel_mrpt/RawlogReader.hpp"
#include "travel_mrpt/TravelFilter.hpp"

namespace fs = std::filesystem;
using mrpt::poses::CPose3D;

namespace travel::apps {

namespace {

CPose3D toPose(const Eigen::Isometry3d& T) {
    mrpt::math::CMatrixDouble44 m;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m(r, c) = T.matrix()(r, c);
    return CPose3D(m);
}

}  // namespace

std::optional<CPose3D> PoseFileSource::at(double t, std::size_t frame) const {
    if (trajectory.timed()) {
        const auto T = travel::poseAt(trajectory, t);
        return T ? std::optional<CPose3D>(toPose(*T)) : std::nullopt;
    }
    if (frame < trajectory.size()) return toPose(trajectory.poses[frame]);
    return std::nullopt;
}

namespace {
// TRAVEL's note on the sensor mount (an `auto` estimate, or a configured value far from the
// ground), on the one frame that has it.
void reportMount(const Options& o, const travel_mrpt::CTraversabilityMap& map,
                 ProgressLine& progress) {
    const travel::MountNote& note = map.lastFrame().result.mount;
    if (note && o.verbosity != Verbosity::Quiet)
        progress.note(mountNoteLine("travel-map", "", note));
}
}  // namespace

void mapRawlog(const Options& o, travel_mrpt::CTraversabilityMap& map, Stats& stats,
               const std::optional<PoseFileSource>& pose_file) {
    travel_mrpt::RawlogReader reader(o.input);
    // Pose sources, by priority: the pose file, then the rawlog's motion (SensoryFrame actions
    // composed from the identity, else the latest CObservationOdometry record).
    travel_mrpt::RawlogMotion motion(map.filter());
    ProgressLine progress("travel-map", 0, o.verbosity);
    bool warned_no_pose = false;
    std::size_t lidar_seen = 0;
    // One observation, at top level or inside a SensoryFrame: motion records feed the filter and
    // the robot pose, anything else is a LiDAR candidate.
    const auto observation = [&](const mrpt::obs::CObservation::Ptr& obs) {
        if (!obs || motion.process(*obs)) return;
        // An untimed (KITTI) pose file is indexed by LiDAR frame: count every LiDAR observation,
        // also those without a pose or rejected, so one bad frame does not shift the rest.
        const std::size_t frame = lidar_seen;
        if (travel_mrpt::isLidarObservation(*obs)) ++lidar_seen;
        const std::optional<CPose3D> pose =
            pose_file ? pose_file->at(mrpt::Clock::toDouble(obs->timestamp), frame)
                      : motion.robotPose();
        if (pose_file && !pose) {
            ++stats.no_pose;
            return;
        }
        if (!pose && !warned_no_pose && o.verbosity != Verbosity::Quiet) {
            warned_no_pose = true;  // once, when it happens, not after the progress line
            progress.note("travel-map: warning: " + o.input + ": LiDAR frame " +
                          std::to_string(stats.lidar + stats.rejected + 1) +
                          " comes before any robot pose (no actions, odometry or pose file): "
                          "frames without a pose are mapped at the identity pose");
        }
        if (map.insertObservation(*obs, pose ? *pose : CPose3D())) {
            reportMount(o, map, progress);
            stats.times.push_back(map.lastInsertTimes());
            ++stats.inserted;
            ++stats.lidar;
        } else {
            ++stats.rejected;
        }
    };
    while (!(o.max_frames > 0 && long(stats.inserted) >= o.max_frames)) {
        const auto record = reader.next();
        if (!record) break;
        ++stats.records;
        if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(record))
            for (const auto& obs : *sf) observation(obs);
        else if (auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(record))
            observation(obs);
        else
            motion.process(*record);  // odometry actions
        // With --max-frames, the end may come before the end of the file.
        const double frames = o.max_frames > 0 ? double(stats.inserted) / double(o.max_frames) : 0;
        progress.update(stats.inserted, std::max(reader.fractionRead(), frames));
        throwIfInterrupted();  // nothing is written before the map is complete
    }
    progress.finish();
    stats.pose_source = pose_file          ? "pose file " + o.poses
                        : motion.actions() ? "odometry actions of the SensoryFrames (" +
                                                 std::to_string(motion.actions()) + " increments)"
                        : motion.hasOdometry() ? "odometry in the rawlog"
                                               : "none (identity poses)";
}

fs::path sequenceFolder(const travel::ScanList& scans, const std::string& input) {
    return scans.sequence_dir.empty() ? input : scans.sequence_dir;
}

void mapKitti(const Options& o, const travel::ScanList& scans, travel_mrpt::CTraversabilityMap& map,
              Stats& stats, std::optional<PoseFileSource> pose_file) {
    const std::vector<std::string>& files = scans.files;
    const fs::path dir = sequenceFolder(scans, o.input);
    std::string calib = o.calib;
    if (calib.empty() && fs::exists(dir / "calib.txt")) calib = (dir / "calib.txt").string();
    if (pose_file && !pose_file->trajectory.timed() && o.verbosity != Verbosity::Quiet) {
        if (calib.empty())
            std::cerr << "travel-map: warning: no calib.txt: the poses are used as LiDAR poses\n";
        if (pose_file->trajectory.size() < files.size())
            std::cerr << "travel-map: warning: " << pose_file->trajectory.size() << " poses for "
                      << files.size() << " scans: the scans without a pose are skipped\n";
    }
    if (pose_file && !pose_file->trajectory.timed() && !calib.empty())
        travel::kittiCameraToLidar(pose_file->trajectory, travel::readKittiCalibTr(calib));
    if (!pose_file && o.verbosity != Verbosity::Quiet)
        std::cerr << "travel-map: warning: " << o.input
                  << " has no robot poses (no poses.txt or --poses): every frame is mapped at "
                     "the identity pose\n";
    const std::size_t count =
        o.max_frames > 0 ? std::min(files.size(), std::size_t(o.max_frames)) : files.size();
    ProgressLine progress("travel-map", count, o.verbosity);
    travel::PointCloud cloud;
    auto obs = mrpt::obs::CObservationPointCloud::Create();
    auto points = mrpt::maps::CPointsMapXYZI::Create();
    obs->pointcloud = points;
    obs->sensorLabel = "velodyne";
    for (std::size_t k = 0; k < files.size(); ++k) {
        if (o.max_frames > 0 && long(stats.inserted) >= o.max_frames) break;
        ++stats.records;
        std::optional<CPose3D> pose;
        if (pose_file) {
            pose = pose_file->at(0.1 * double(k), k);
            if (!pose) {
                ++stats.no_pose;
                continue;
            }
        }
        travel::readScan(files[k], cloud, o.format);  // errors name the file
        points->clear();
        points->reserve(cloud.size());
        for (std::size_t i = 0; i < cloud.size(); ++i)
            points->insertPointFast(cloud.x[i], cloud.y[i], cloud.z[i]);
        points->mark_as_modified();
        obs->timestamp = mrpt::Clock::fromDouble(0.1 * double(k));  // KITTI: 10 Hz
        ++stats.lidar;
        if (map.insertObservation(*obs, pose ? *pose : CPose3D())) {
            reportMount(o, map, progress);
            stats.times.push_back(map.lastInsertTimes());
            ++stats.inserted;
        } else
            ++stats.rejected;
        progress.update(k + 1);
        throwIfInterrupted();  // nothing is written before the map is complete
    }
    progress.finish();
    stats.pose_source = pose_file ? "pose file " + o.poses : "none (identity poses)";
}

}  // namespace travel::apps
