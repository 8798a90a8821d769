// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "MapSources.hpp"

#include <mrpt/maps/CPointsMapXYZI.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <mutex>

#include "Interrupt.hpp"
#include "OrderedWork.hpp"
#include "Progress.hpp"
#include "travel/ThreadCpuClock.hpp"
#include "travel/eval/KittiIO.hpp"
#include "travel/traversability/FrameFusion.hpp"
#include "travel_mrpt/ObservationAdapters.hpp"
#include "travel_mrpt/RawlogReader.hpp"
#include "travel_mrpt/TravelFilter.hpp"

namespace fs = std::filesystem;
using mrpt::poses::CPose3D;
using Clock = std::chrono::steady_clock;

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
double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// TRAVEL's note on the sensor mount (an `auto` estimate, or a configured value far from the
// ground), on the one frame that has it.
void reportMount(const Options& o, const travel_mrpt::TravelFrame& frame, ProgressLine& progress) {
    const travel::MountNote& note = frame.result.mount;
    if (note && o.verbosity != Verbosity::Quiet)
        progress.note(mountNoteLine("travel-map", "", note));
}

}  // namespace

void mapRawlog(const Options& o, travel_mrpt::CTraversabilityMap& map, Stats& stats,
               const std::optional<PoseFileSource>& pose_file, Notes& notes) {
    travel_mrpt::RawlogReader reader(o.input);
    // Pose sources, by priority: the pose file, then the rawlog's motion (SensoryFrame actions
    // composed from the identity, else the latest CObservationOdometry record).
    travel_mrpt::RawlogMotion motion(map.filter());
    ProgressLine progress("travel-map", 0, o.verbosity);
    const Notes::Attached attached(notes, progress);
    bool warned_no_pose = false;
    long record = -1;  // the index of the record being read
    std::size_t lidar_seen = 0;
    double read_ms = 0;  // reading since the last mapped frame
    Clock::time_point last_fused = Clock::now();
    // One observation, at top level or inside a SensoryFrame: motion records feed the filter and
    // the robot pose, LiDAR observations are mapped, anything else (cameras, TRAVEL's own outputs
    // of a travel-rawlog run) is no LiDAR frame.
    const auto observation = [&](const mrpt::obs::CObservation::Ptr& obs) {
        if (!obs || motion.process(*obs) || !travel_mrpt::isLidarObservation(*obs)) return;
        // An untimed (KITTI) pose file is indexed by LiDAR frame: count every LiDAR observation,
        // also those without a pose or rejected, so one bad frame does not shift the rest.
        const std::size_t frame = lidar_seen++;
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
            reportMount(o, map.lastFrame(), progress);
            stats.times.push_back({read_ms, map.lastInsertTimes(), msSince(last_fused), {}});
            read_ms = 0;
            last_fused = Clock::now();
            ++stats.inserted;
            ++stats.lidar;
        } else {
            ++stats.rejected;
            notes.oncePerReason(travel_mrpt::RawlogReader::where(o.input, record),
                                "not mapped: " + map.lastRejection());
        }
    };
    while (!(o.max_frames > 0 && long(stats.inserted) >= o.max_frames)) {
        const auto read_start = Clock::now();
        const auto object = reader.next();
        read_ms += msSince(read_start);
        if (!object) break;
        record = reader.index() - 1;
        ++stats.records;
        if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(object))
            for (const auto& obs : *sf) observation(obs);
        else if (auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(object))
            observation(obs);
        else
            motion.process(*object);  // odometry actions
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
              Stats& stats, std::optional<PoseFileSource> pose_file, Notes& notes) {
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
    const Notes::Attached attached(notes, progress);  // notes come from the producing threads

    // Each scan is read straight into travel's cloud, segmented and fused into the grid on the
    // producing thread (map.segment, map.fuseGrid), then its rays update the OctoMap on the
    // calling thread (map.fuseVoxels). With -j >= 2 two producing threads take turns, one at a
    // time and in order (the filter's and the grid's state go from frame to frame), while the
    // calling thread updates the OctoMap with the previous frames in order: the map is the one
    // of -j 1. The OctoMap update is the larger half (docs/map.md).
    struct Scan {
        travel_mrpt::TravelFrame frame;  // frame.cloud: the scan as read
        travel::RayEnds rays;            // filled by fuseGrid, for fuseVoxels
        std::optional<CPose3D> pose;
        enum class State { Skipped, NoPose, Rejected, Fused } state = State::Skipped;
        std::string rejection;  // map.lastRejection() of a Rejected scan
        FrameTimes times;
        double produce_cpu_ms = 0;
    };
    std::mutex turn_mutex;
    std::condition_variable turn_changed;
    std::size_t turn = 0;  // the scan whose turn it is to be read and segmented
    // Frames fused into the grid: with --max-frames the producing side decides where to stop
    // (it is ahead of the OctoMap). Guarded by the turns.
    long fused = 0;
    const auto produce = [&](unsigned, std::size_t k, Scan& scan) {
        {
            std::unique_lock<std::mutex> lock(turn_mutex);
            turn_changed.wait(lock, [&] { return turn == k; });
        }
        struct NextTurn {  // also when reading fails: the error surfaces in order, when consumed
            std::mutex& m;
            std::condition_variable& c;
            std::size_t& t;
            ~NextTurn() {
                {
                    std::lock_guard<std::mutex> lock(m);
                    ++t;
                }
                c.notify_all();
            }
        } next_turn{turn_mutex, turn_changed, turn};
        using State = Scan::State;
        scan.state = State::Skipped;
        scan.pose.reset();
        if (o.max_frames > 0 && fused >= o.max_frames) return;
        if (pose_file) {
            scan.pose = pose_file->at(0.1 * double(k), k);
            if (!scan.pose) {
                scan.state = State::NoPose;
                return;
            }
        }
        const double cpu_start = threadCpuMs();
        const auto read_start = Clock::now();
        travel::readScan(files[k], scan.frame.cloud, o.format);  // errors name the file
        scan.times.read_ms = msSince(read_start);
        const CPose3D pose = scan.pose ? *scan.pose : CPose3D();
        // The cloud is segmented in place (TravelFilter copies it into frame.cloud: itself).
        scan.state = State::Rejected;
        if (map.segment(scan.frame.cloud, pose,
                        mrpt::Clock::fromDouble(0.1 * double(k)),  // KITTI: 10 Hz
                        scan.frame, "velodyne")) {
            scan.times.map.segment_ms = scan.frame.process_ms;
            scan.times.map.grid_ms = map.fuseGrid(scan.frame, pose, scan.rays);
            scan.state = State::Fused;
            ++fused;
        } else {
            scan.rejection = map.lastRejection();  // the next scan's segment() replaces it
        }
        scan.produce_cpu_ms = threadCpuMs() - cpu_start;
    };
    Clock::time_point last_fused = Clock::now();
    const auto consume = [&](std::size_t k, Scan& scan) {
        using State = Scan::State;
        if (scan.state == State::Skipped) return;
        ++stats.records;
        if (scan.state == State::NoPose) {
            ++stats.no_pose;
            return;
        }
        ++stats.lidar;
        if (scan.state == State::Fused) {
            const double cpu_start = threadCpuMs();
            scan.times.map.octomap_ms = map.fuseVoxels(scan.rays);
            reportMount(o, scan.frame, progress);
            scan.times.interval_ms = msSince(last_fused);
            last_fused = Clock::now();
            scan.times.cpu_ms[0] = scan.produce_cpu_ms;
            scan.times.cpu_ms[1] = threadCpuMs() - cpu_start;
            stats.times.push_back(scan.times);
            ++stats.inserted;
        } else {
            ++stats.rejected;
            notes.oncePerReason(files[k], "not mapped: " + scan.rejection);
        }
        progress.update(k + 1);
        throwIfInterrupted();  // nothing is written before the map is complete
    };
    // Two producing threads, so that one is ready with the next scan while the other waits for
    // a free slot; more would only wait.
    forEachInOrder<Scan>(
        files.size(), std::min(o.jobs, 2u), [] { return false; }, [](unsigned) {}, produce,
        consume);
    progress.finish();
    stats.pose_source = pose_file ? "pose file " + o.poses : "none (identity poses)";
}

}  // namespace travel::apps
