// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Output of the above-ground object segmentation: one summary per cluster, for map layers and
// navigation. Coordinates are in the aligned frame (sensor origin, z up).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace travel {

struct ClusterSummary {
    uint32_t id = 0;  ///< > 0, equal to Result::cluster_id of its points
    uint32_t num_points = 0;
    uint32_t first_point = 0;  ///< smallest input index: ids are ordered by it
    Eigen::Vector3f centroid{0.f, 0.f, 0.f};
    Eigen::Vector3f aabb_min{0.f, 0.f, 0.f}, aabb_max{0.f, 0.f, 0.f};
    /// Oriented box: yaw of its length axis [rad], centre, and full extents (length >= width,
    /// height along z). From the 2-D PCA of the points' xy.
    float obb_yaw = 0.f;
    Eigen::Vector3f obb_center{0.f, 0.f, 0.f};
    Eigen::Vector3f obb_extent{0.f, 0.f, 0.f};
    /// Ground height under the centroid from the terrain model (NaN if unknown), and the
    /// highest point above it [m].
    float ground_z = 0.f;
    float height_above_ground = 0.f;
    /// Tracking across frames (travel::Tracker fills these; all zero when nothing tracks):
    /// the id of the confirmed track this cluster continues (0 = none yet), the track's
    /// velocity over the ground expressed in this frame's aligned axes [m/s] (ego-motion
    /// removed) with its 1-sigma per axis, and whether it moves (decided with hysteresis).
    uint32_t track_id = 0;
    Eigen::Vector3f velocity{0.f, 0.f, 0.f};
    Eigen::Vector3f velocity_sigma{0.f, 0.f, 0.f};
    bool moving = false;
};

}  // namespace travel
