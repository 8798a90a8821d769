// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Obstacles from TRAVEL's ground model (for a 3-D reactive navigator such as MRPT's
// CReactiveNavigationSystem3D, through travel_mrpt::TravelObstacleSource): every point TRAVEL
// did not call ground, at xy in the levelled robot frame and z = its height above the LOCAL
// ground model (the plane of the terrain node under it), so that the navigator's height slices
// (which start at z = 0) follow slopes instead of cutting into them. Reported:
//   - non-ground points higher than max_step_height above the local ground (a lower bump, or a
//     step the robot can climb, is not an obstacle);
//   - points of too-steep terrain nodes (TRAVEL's NodeClass::Obstacle: kerb faces, steep ramps)
//     higher than report_floor above the local ground;
//   - ground of a traversable node whose plane is more than max_step_height above a
//     neighbouring traversable node's plane at their shared edge (a step or kerb whose top
//     TRAVEL accepted as terrain), at z = that step height. The step must also show in the
//     seen ground (each node's mean point against the other node's plane), and both nodes'
//     points must spread at least step_min_spread across: a plane fitted to one ring's arc or
//     to a small patch (at the edge of the blind zone around the robot) has an unknown tilt,
//     and extrapolated half a cell it made 0.15 m "steps" on a 15-degree slope.
// Points higher than max_height above the local ground (overhangs, trees above the robot) are
// dropped.
//
// Height above the local ground of a non-ground point: travel::TerrainModel::heightAboveGround
// (the lowest of its heights over the ground planes of its cell and the 4 neighbouring cells, so
// that the foot of a ramp is not lifted by a flat node's plane); when there is none, over the
// nearest node with ground (TerrainModel::groundPlane) within ground_search_radius; otherwise
// over the robot's own base plane. Steps: travel::TerrainModel::stepBetween.
// Input: TRAVEL's result and the aligned cloud it labelled (Pipeline::aligned(),
// TravelFrame::aligned): the points are used as TRAVEL saw them (levelled and, with deskew,
// deskewed), so obstacle xy are exactly those of the labelled points. No MRPT.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstddef>
#include <vector>

#include "travel/Config.hpp"
#include "travel/Preprocessing.hpp"
#include "travel/Result.hpp"
#include "travel/TerrainModel.hpp"
#include "travel/traversability/StaticScene.hpp"

namespace travel {

/// Robot-centric obstacle points (x forward, y left, z up; metres), structure of arrays.
struct ObstaclePointCloud {
    std::vector<float> x, y, z;
    std::size_t size() const { return x.size(); }
    void clear() { x.clear(), y.clear(), z.clear(); }
    void push_back(float px, float py, float pz) {
        x.push_back(px), y.push_back(py), z.push_back(pz);
    }
};

class TravelObstacles {
  public:
    /// The nav section's obstacle keys (max_step_height ... step_min_spread; the memory keys are
    /// the obstacle source's).
    explicit TravelObstacles(const NavSection& options = {});
    const NavSection& options() const { return options_; }
    /// NavSection::validate(), then keeps `options`. Throws ConfigError naming the key.
    void setOptions(const NavSection& options);

    /// Appends the obstacles of one frame to `out`, in the levelled robot frame (xy from the
    /// robot origin, z above the local ground). `aligned` is the cloud `result` labels (same
    /// size); sensor_on_robot places the sensor on the robot (origin on the ground under the
    /// robot). Throws std::invalid_argument when the sizes differ. Buffers are reused.
    /// With `moving` given, the obstacle points of clusters the tracker flags moving
    /// (ClusterSummary::moving), and every obstacle point within MovingFootprints::kMargin of such
    /// a cluster's oriented box, go there instead of into `out`: a memory or a static map must not
    /// keep them (a trail of obstacles along the mover's path).
    void compute(const Result& result, const AlignedCloud& aligned,
                 const Eigen::Isometry3f& sensor_on_robot, ObstaclePointCloud& out,
                 ObstaclePointCloud* moving = nullptr);

    /// Appends to `out` (same frame as compute()) the predicted footprint of every cluster
    /// flagged moving: the outline of its oriented box swept along its velocity over
    /// predict_seconds (the convex hull of the box now and the box then), a point every
    /// kOutlineSpacing, in a column from report_floor to the cluster's height above the ground
    /// (at most max_height) every `column_step`. A reactive navigator then keeps out of where
    /// the object is going, not only of where it is. Nothing without tracking (no cluster moves).
    void predictMoving(const Result& result, const AlignedCloud& aligned,
                       const Eigen::Isometry3f& sensor_on_robot, ObstaclePointCloud& out,
                       float column_step = 0.25f) const;
    /// [m] between the points of a predicted outline: less than a navigator's robot is wide.
    static constexpr float kOutlineSpacing = 0.1f;

  private:
    void findGroundNodes(const TerrainModel& terrain);
    void findSteps(const TerrainModel& terrain);

    NavSection options_;
    std::vector<int> ground_node_;    // per node: node whose ground is its reference (-1 none)
    std::vector<float> step_height_;  // per node: step above a neighbour (0 = none)
    MovingFootprints movers_;         // this frame's moving clusters (compute())
};

}  // namespace travel
