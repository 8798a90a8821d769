// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Obstacle points for MRPT's reactive navigators (CRobot2NavInterface::senseObstacles()), from
// one LiDAR frame at a time. A source turns a frame into robot-centric points (x forward, y left,
// z up, metres) and hands them over to the navigator thread:
//
//   sensor thread:     source.update(frame);              // computes, then publishes
//   navigator thread:  source.latest(points_map, stamp);  // copies the latest published set
//
// update() computes into a private buffer, then swaps it with the published one under a mutex:
// the navigator never sees a half-written set, and neither side waits for the other's work.
// Buffers are reused across frames (no allocation once warm).
//
// Optional short-term memory (travel::ObstacleMemory): obstacles of earlier frames are kept for
// `memory_seconds` while they stay within `memory_radius` of the robot (moved with the robot's
// odometry), because a LiDAR on a robot does not see the ground right around itself. Moving
// objects (tracking on: travel::ClusterSummary::moving) are not remembered: a source hands them,
// with their predicted paths, for the current frame only.
#pragma once

#include <mrpt/core/Clock.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstddef>
#include <mutex>
#include <string>
#include <vector>

#include "travel/Config.hpp"
#include "travel/PointCloud.hpp"
#include "travel/Preprocessing.hpp"
#include "travel/Result.hpp"
#include "travel/traversability/ObstacleMemory.hpp"
#include "travel/traversability/TravelObstacles.hpp"

namespace mrpt::maps {
class CSimplePointsMap;
}

namespace travel_mrpt {

struct TravelFrame;

/// What a source needs from one LiDAR frame (pointers stay owned by the caller).
struct ObstacleFrame {
    const travel::PointCloud* cloud = nullptr;  ///< sensor frame
    /// TRAVEL's result for `cloud` (labels + terrain in the aligned frame) and the aligned
    /// cloud it labels (TravelFrame::result, TravelFrame::aligned: levelled and deskewed as
    /// TRAVEL saw the points); null for sources that do not use them.
    const travel::Result* result = nullptr;
    const travel::AlignedCloud* aligned = nullptr;
    /// Sensor pose on the robot (robot frame: origin on the ground under the robot, x forward).
    Eigen::Isometry3f sensorOnRobot = Eigen::Isometry3f::Identity();
    /// Robot pose in the odometry frame (x, y [m], yaw [rad]): moves the memory between frames.
    Eigen::Vector3d robotOdometry = Eigen::Vector3d::Zero();
    mrpt::Clock::time_point timestamp{};
    /// The map source (MapObstacleSource): the filter's whole frame (sensor pose, alignment)
    /// and the robot's 3-D pose in the map's world frame, where the frame is fused.
    const TravelFrame* travel = nullptr;
    Eigen::Isometry3d robotPose = Eigen::Isometry3d::Identity();
};

/// Robot-centric obstacle points (structure of arrays) and the time of their frame.
struct ObstaclePoints : travel::ObstaclePointCloud {
    mrpt::Clock::time_point timestamp{};
};

class ObstacleSource {
  public:
    virtual ~ObstacleSource() = default;
    /// Short name for logs and file names ("travel", "raw", "threshold").
    virtual std::string name() const = 0;

    /// The nav section's memory keys (memory_seconds, memory_radius); forgets what was kept.
    /// NavSection::validate() first: throws travel::ConfigError naming the key.
    void setMemory(const travel::NavSection& nav);
    const travel::NavSection& memory() const { return memory_; }

    /// Sensor side: computes the obstacles of `frame` and publishes them. Throws
    /// std::invalid_argument when the frame lacks what the source needs (no cloud for the
    /// robot-frame sources, no result or aligned cloud for the TRAVEL source, sizes that do not
    /// match).
    void update(const ObstacleFrame& frame);

    /// Navigator side: copies the latest published obstacles. False before the first update().
    bool latest(ObstaclePoints& out) const;
    /// Same, into the navigator's points map (cleared first); `stamp` in MRPT's TTimeStamp sense.
    bool latest(mrpt::maps::CSimplePointsMap& out, mrpt::Clock::time_point& stamp) const;

  protected:
    /// Appends the obstacles of this frame (robot frame) to `out` (already cleared), and to
    /// `transient` (already cleared) those of this frame only: moving objects and their predicted
    /// paths (travel::TravelObstacles::predictMoving), which the memory must not keep.
    virtual void compute(const ObstacleFrame& frame, ObstaclePoints& out,
                         travel::ObstaclePointCloud& transient) = 0;

  private:
    travel::NavSection memory_;
    std::mutex update_mutex_;               // one update() at a time
    ObstaclePoints work_;                   // written by update() only
    travel::ObstaclePointCloud transient_;  // written by update() only
    travel::ObstacleMemory recall_;         // written by update() only
    mutable std::mutex publish_mutex_;
    ObstaclePoints published_;
    bool has_published_ = false;
};

}  // namespace travel_mrpt
