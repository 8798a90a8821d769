// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The comparison obstacle sources: what a user without a ground model feeds the navigator.
// Both take the LiDAR points in the ROBOT frame (sensor mount applied, nothing levelled: on a
// slope the robot frame tilts with the robot) and keep those with min_z <= z <= max_z:
//   raw()              every valid point above the robot's base plane plus a noise margin
//                      (min_z = 0.03 m; the 3-D navigator itself drops z < 0.01 m and bins the
//                      rest into its height slices, as in MRPT's stock reactive3d config);
//   heightThreshold()  the classic "ground = everything lower than h over the sensor's plane"
//                      filter (min_z = 0.25 m: the lowest value with which the robot still
//                      climbs a 15-degree ramp in travel-nav-sim, see docs/navigation.md).
// Neither knows about slopes: that is the point of the comparison.
#pragma once

#include <memory>

#include "travel_mrpt/ObstacleSource.hpp"

namespace travel_mrpt {

class RobotFrameBandSource : public ObstacleSource {
  public:
    /// Throws std::invalid_argument unless min_z < max_z.
    RobotFrameBandSource(std::string name, double min_z, double max_z);
    static std::unique_ptr<RobotFrameBandSource> raw(double min_z = 0.03);
    static std::unique_ptr<RobotFrameBandSource> heightThreshold(double min_z = 0.25);

    std::string name() const override { return name_; }
    double minZ() const { return min_z_; }
    double maxZ() const { return max_z_; }

  protected:
    void compute(const ObstacleFrame& frame, ObstaclePoints& out,
                 travel::ObstaclePointCloud& transient) override;

  private:
    std::string name_;
    double min_z_, max_z_;
};

}  // namespace travel_mrpt
