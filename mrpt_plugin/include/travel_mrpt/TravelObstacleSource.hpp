// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Obstacles from TRAVEL's ground model, for CReactiveNavigationSystem3D: every point TRAVEL
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
#pragma once

#include "travel_mrpt/ObstacleSource.hpp"

namespace travel_mrpt {

struct TravelObstacleOptions {
    double max_step_height = 0.15;  ///< [m] the robot climbs steps and bumps up to this height
    double max_height = 2.0;        ///< [m] ignore points higher above the ground than this
    /// [m] points of too-steep nodes count from this height (the 3-D navigator drops z < 0.01)
    double report_floor = 0.15;
    double ground_search_radius = 3.0;  ///< [m] nearest traversable node for other nodes' points
    /// [m] the step rule only compares nodes whose ground points spread at least this much
    /// (standard deviation) in their second direction: the plane of one ring's arc or of a
    /// small patch is not known away from its points
    double step_min_spread = 0.05;
};

class TravelObstacleSource : public ObstacleSource {
  public:
    explicit TravelObstacleSource(const TravelObstacleOptions& options = {});
    std::string name() const override { return "travel"; }
    const TravelObstacleOptions& options() const { return options_; }
    /// Throws std::invalid_argument on negative heights or radius.
    void setOptions(const TravelObstacleOptions& options);

  protected:
    void compute(const ObstacleFrame& frame, ObstaclePoints& out) override;

  private:
    void findGroundNodes(const travel::TerrainModel& terrain);
    void findSteps(const travel::TerrainModel& terrain);

    TravelObstacleOptions options_;
    std::vector<int> ground_node_;    // per node: node whose plane is its local ground (-1 none)
    std::vector<float> step_height_;  // per node: step above a neighbour (0 = none)
};

}  // namespace travel_mrpt
