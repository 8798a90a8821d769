// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// An independent registration of a drive: MRPT's 2-D ICP (mrpt::slam::CICP, icpClassic) of
// each scan's above-ground points (a fixed height band, not TRAVEL's labels) to the previous
// scan's, frame to frame. It shares no code with travel::ScanRegistration, so the pose file
// travel-kitti --track writes can be checked against it (issue 19; docs/tracking.md).
#pragma once

#include <Eigen/Geometry>
#include <memory>

#include "travel/PointCloud.hpp"

namespace travel::test {

class CicpOdometry {
  public:
    /// [m] xy range of the points used, and their height band in the sensor frame (above the
    /// ground of a car-mounted LiDAR ~1.7 m up, below the tree tops).
    static constexpr double kMinRange = 3.0, kMaxRange = 50.0, kMinZ = -1.2, kMaxZ = 2.0;
    /// Every kStride-th point of the band (~4 k per HDL-64E scan).
    static constexpr int kStride = 10;

    CicpOdometry();
    ~CicpOdometry();
    /// The scan's pose in the first scan's frame (the first is the identity); planar (x, y,
    /// yaw). The motion of the previous step is the initial guess.
    Eigen::Isometry3d add(const PointCloud& cloud);

  private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace travel::test
