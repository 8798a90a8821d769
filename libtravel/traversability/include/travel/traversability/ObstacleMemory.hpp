// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Short-term memory of robot-centric obstacle points: obstacles of earlier frames are kept for
// a while and moved with the robot's odometry, while they stay near the robot, because a LiDAR
// on a robot does not see the ground right around itself (below its lowest beam). Buffers are
// recycled (no allocation once warm).
//
// Times are integers of the caller's clock (MRPT: 100 ns ticks), so that an age equal to the
// limit is decided exactly, whatever the epoch.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <deque>
#include <vector>

#include "travel/traversability/TravelObstacles.hpp"

namespace travel {

class ObstacleMemory {
  public:
    /// Keep obstacles for max_age (clock units; < 0: no memory) while within `radius` [m] of
    /// the robot (xy). Forgets what was kept.
    void configure(int64_t max_age, double radius);

    /// `out` holds this frame's obstacles (robot frame at `odometry`: x, y [m], yaw [rad]):
    /// appends the remembered ones still young enough and near enough, moved into this robot
    /// frame, then remembers this frame's own obstacles within 2 * radius.
    void recallAndRemember(int64_t time, const Eigen::Vector3d& odometry, ObstaclePointCloud& out);

  private:
    struct Remembered {
        int64_t time = 0;
        Eigen::Vector3d odometry;   ///< robot pose when seen
        ObstaclePointCloud points;  ///< robot frame then
    };
    int64_t max_age_ = -1;
    double radius_ = 0;
    std::deque<Remembered> past_;
    std::vector<ObstaclePointCloud> spare_;  ///< recycled buffers
};

}  // namespace travel
