// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The map-backed obstacle source: the navigator senses the obstacles the robot has seen, not
// only those of the current frame. Each frame (ObstacleFrame::travel, at ObstacleFrame::
// robotPose in the world)
//   1. is fused into a CTraversabilityMap (grid + OctoMap: the layer users save, plan on and
//      open in MRPT's tools), and
//   2. gives its TRAVEL obstacles (travel::TravelObstacles: the same rules and heights above the
//      local ground as TravelObstacleSource) to an obstacle grid of the map's geometry and
//      fusion rules (travel::TraversabilityGrid: log-odds per cell, one update per cell and
//      frame; a cell with reported obstacle points gains logodds_obstacle, a cell with only
//      ground points in a later frame loses logodds_ground).
// The navigator gets, in the levelled robot frame, every cell of the obstacle grid within
// `horizon` whose log-odds exceed obstacle_threshold, as its square grown by `margin` (its
// corners), in a column from the lowest to the highest height above the local ground TRAVEL
// last reported there (every column_step).
//
// Clearing is by free evidence only (clear-on-free): a cell is forgotten once later frames see
// ground there (from +3.5, the clamp, 8 ground-only frames at -0.4 bring it under +0.5). No
// decay: an obstacle behind the robot or in the LiDAR's blind zone is not seen again, and
// forgetting it with time is what made the robot pass kerbs close and re-enter dead ends; a
// moving thing uncovers the ground it stood on, and that ground clears its old cells.
#pragma once

#include <memory>
#include <vector>

#include "travel/traversability/TravelObstacles.hpp"
#include "travel/traversability/TraversabilityGrid.hpp"
#include "travel_mrpt/ObstacleSource.hpp"
#include "travel_mrpt/TraversabilityMapOptions.hpp"

namespace travel_mrpt {

class CTraversabilityMap;

struct MapSourceOptions {
    double horizon = 5.0;  ///< [m] cells within this xy distance are reported (ref_distance)
    /// [m] each obstacle cell is reported as its square grown by this much: the navigator passes
    /// reported edges within a few cm, and a cell centre can lie half a cell inside the obstacle.
    double margin = 0.1;
    /// [m] a cell is reported as a column from the lowest to the highest height TRAVEL last
    /// reported in it, one layer of points every column_step: keep it at most the robot's
    /// shortest height level, so that a wall is in every level it spans.
    double column_step = 0.25;
};

class MapObstacleSource : public ObstacleSource {
  public:
    /// `map`: geometry, OctoMap and fusion keys (its filter options are not used: frames come
    /// segmented); `nav`: TRAVEL's obstacle rule (its memory keys are not used: the map is the
    /// memory). Throws travel::ConfigError naming the key.
    explicit MapObstacleSource(const TraversabilityMapOptions& map,
                               const travel::NavSection& nav = {},
                               const MapSourceOptions& options = {});
    ~MapObstacleSource() override;
    std::string name() const override { return "map"; }

    // For the thread that calls update() (planning, saving):
    CTraversabilityMap& map() { return *map_; }
    const CTraversabilityMap& map() const { return *map_; }
    /// TRAVEL's obstacles fused over the frames (see the file comment).
    const travel::TraversabilityGrid& obstacleGrid() const { return obstacles_grid_; }
    /// The obstacle grid's cell holds an obstacle (log-odds above obstacle_threshold).
    bool obstacleCell(long cell) const;
    /// Lowest and highest heights above the local ground TRAVEL reported in the cell in the
    /// last frame that saw obstacle points there [m] (0, 0: none yet).
    float obstacleLow(long cell) const { return low_[cell]; }
    float obstacleHigh(long cell) const { return high_[cell]; }
    /// Per cell, what a planner needs: Obstacle where the obstacle grid says so, else the map's
    /// state (Traversable / Unknown; the map's own Obstacle cells stay Obstacle); the map's
    /// terrain slope [deg] (NaN where unknown).
    void plannerGrid(std::vector<travel::CellState>& states, std::vector<float>& slopes) const;
    /// Milliseconds of the last update: map fusion (grid + OctoMap), obstacle rule + grid +
    /// reporting.
    double lastMapMs() const { return map_ms_; }
    double lastSensingMs() const { return sensing_ms_; }
    /// Both together in the thread's CPU time [ms] (less sensitive to other processes).
    double lastCpuMs() const { return cpu_ms_; }

  protected:
    void compute(const ObstacleFrame& frame, ObstaclePoints& out,
                 travel::ObstaclePointCloud& transient) override;

  private:
    void resetObstacles();  // the obstacle grid on the map's geometry, empty

    MapSourceOptions options_;
    std::unique_ptr<CTraversabilityMap> map_;
    travel::TravelObstacles rule_;
    travel::ObstaclePointCloud frame_points_;  // this frame's TRAVEL obstacles, robot frame
    travel::TraversabilityGrid obstacles_grid_;
    std::vector<float> low_, high_;              // per cell: last reported heights above the ground
    std::vector<float> frame_low_, frame_high_;  // per cell: this frame's (NaN: none)
    std::vector<long> frame_cells_;
    double map_ms_ = 0, sensing_ms_ = 0, cpu_ms_ = 0;
};

}  // namespace travel_mrpt
