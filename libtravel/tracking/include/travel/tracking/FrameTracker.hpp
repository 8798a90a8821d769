// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Tracking over a sequence of segmented frames, in input order: each frame's pose (given, or
// estimated by registering its non-ground points with the previous frame's, ScanOdometry), then
// the Tracker on its clusters in that world frame. What travel-kitti --track runs per frame.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "travel/Clusters.hpp"
#include "travel/PointCloud.hpp"
#include "travel/tracking/ScanRegistration.hpp"
#include "travel/tracking/Tracker.hpp"

namespace travel {

class FrameTracker {
  public:
    explicit FrameTracker(
        const TrackingParams& tracking = {},
        const RegistrationParams& registration = RegistrationParams::nonGroundOdometry());

    /// One frame: `cloud` in the sensor frame with one label per point, `aligned_rotation`
    /// sensor -> aligned (the frame of `clusters`). world_T_sensor: the frame's pose when known;
    /// nullptr: registered (non-ground points within registration_range of the sensor) to the
    /// previous frame. Returns the pose used (the first frame's estimate is the identity) and
    /// fills the clusters' tracking fields (Tracker::update). cluster_id: one per point
    /// (travel::Result::cluster_id); with it each track measures its object's displacement from
    /// the points' shape (ClusterSamples, TrackShapeAlignment.hpp), without it from its centroid.
    Eigen::Isometry3d update(double t, const PointCloud& cloud,
                             const std::vector<PointClass>& labels,
                             const Eigen::Matrix3f& aligned_rotation,
                             std::vector<ClusterSummary>& clusters,
                             const Eigen::Isometry3d* world_T_sensor = nullptr,
                             const std::vector<uint32_t>* cluster_id = nullptr);

    const Tracker& tracker() const { return tracker_; }
    /// The last frame's aligned frame in the world (the frame of its clusters).
    const Eigen::Isometry3d& worldTAligned() const { return world_T_aligned_; }
    /// [m] xy range of the points registered (farther ones are sparse: few normals).
    static constexpr double registration_range = 50.0;

  private:
    ScanOdometry odometry_;
    Tracker tracker_;
    std::vector<Eigen::Vector3d> points_;
    ClusterSamples samples_;
    Eigen::Isometry3d world_T_aligned_ = Eigen::Isometry3d::Identity();
};

}  // namespace travel
