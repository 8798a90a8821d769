// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/tracking/FrameTracker.hpp"

namespace travel {

FrameTracker::FrameTracker(const TrackingParams& tracking, const RegistrationParams& registration)
    : odometry_(registration), tracker_(tracking) {}

Eigen::Isometry3d FrameTracker::update(double t, const PointCloud& cloud,
                                       const std::vector<PointClass>& labels,
                                       const Eigen::Matrix3f& aligned_rotation,
                                       std::vector<ClusterSummary>& clusters,
                                       const Eigen::Isometry3d* world_T_sensor,
                                       const std::vector<uint32_t>* cluster_id) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    if (world_T_sensor) {
        pose = *world_T_sensor;
    } else {
        // Non-ground points: the ground constrains little in xy and yaw, and a flat road lets
        // ICP slide along it.
        points_.clear();
        constexpr double r2 = registration_range * registration_range;
        for (std::size_t i = 0; i < cloud.size(); ++i) {
            if (labels[i] != PointClass::NonGround) continue;
            const Eigen::Vector3d p(cloud.x[i], cloud.y[i], cloud.z[i]);
            if (p.head<2>().squaredNorm() <= r2) points_.push_back(p);
        }
        pose = odometry_.add(points_);
    }
    Eigen::Isometry3d sensor_T_aligned = Eigen::Isometry3d::Identity();
    sensor_T_aligned.linear() = aligned_rotation.cast<double>().transpose();
    world_T_aligned_ = pose * sensor_T_aligned;
    if (cluster_id) samples_.build(cloud, *cluster_id, aligned_rotation, clusters);
    tracker_.update(t, world_T_aligned_, clusters, cluster_id ? &samples_ : nullptr);
    return pose;
}

}  // namespace travel
