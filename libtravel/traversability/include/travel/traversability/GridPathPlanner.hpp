// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Global path planning on the traversability grid (Eigen/std only): A* over the cells,
// 8-connected, on a cost that knows what the map knows. Obstacle cells, inflated by the
// robot's radius, are forbidden; every move costs its length times
//   1 + unknown_cost            (cell never observed: the goal may lie behind unseen ground)
//     + slope_cost * slope/max  (steeper ground costs more; steeper than max_slope_deg: forbidden)
//     + proximity_cost * (1 - (d - radius) / (comfort - radius))  within `comfort` of an obstacle
// so that paths keep off walls and kerbs where there is room. Distances to obstacles are exact
// (Euclidean, cell centres) up to comfort_radius: each obstacle cell stamps its disk.
//
//   GridPathPlanner planner;
//   planner.setGrid(geometry, cells, slopes);          // CellState per cell, slope [deg] or NaN
//   if (planner.plan(start, goal, path)) ...           // world xy, start to goal
//   planner.blocked(path)                              // a path cell now forbidden
//
// Decided on a measurement (docs/navigation.md): MRPT's planner (CPathPlanningCircularRobot on
// the exported COccupancyGridMap2D) treats unknown cells as occupied or free only, and knows no
// slope; this search on the grid itself takes a few ms on the simulator's maps.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "travel/Config.hpp"
#include "travel/traversability/TraversabilityGrid.hpp"

namespace travel {

struct GridPlannerOptions {
    /// [m] cells closer than this to an obstacle cell's centre are forbidden (the robot's
    /// half-width and a little: the path's centre line keeps this from obstacles)
    double robot_radius = 0.35;
    double comfort_radius = 0.8;  ///< [m] closer than this to an obstacle costs extra
    double proximity_cost = 2.0;  ///< extra cost factor at robot_radius (0 at comfort_radius)
    double unknown_cost = 0.5;    ///< extra cost factor of an unobserved cell
    double slope_cost = 1.0;      ///< extra cost factor at max_slope_deg
    double max_slope_deg = 20.0;  ///< steeper cells are forbidden
    /// Around the start and the goal (within robot_radius) inflated cells are allowed: the
    /// robot may stand closer to an obstacle than robot_radius (real obstacles stay forbidden).
    double waypoint_spacing = 1.0;  ///< [m] waypoints() spacing along the path
};

class GridPathPlanner {
  public:
    explicit GridPathPlanner(const GridPlannerOptions& options = {}) : options_(options) {}
    const GridPlannerOptions& options() const { return options_; }

    /// The grid to plan on: a state and a slope [deg] (NaN: unknown) per cell, index
    /// iy * sizeX + ix as in TraversabilityGrid. Computes the inflation.
    void setGrid(const GridGeometry& geometry, const std::vector<CellState>& states,
                 const std::vector<float>& slopes_deg);

    /// A* from start to goal (world xy). Fills `path` with cell centres from start to goal
    /// (the goal itself last); false when no path exists or either end is outside the grid.
    bool plan(const Eigen::Vector2d& start, const Eigen::Vector2d& goal,
              std::vector<Eigen::Vector2d>& path);

    /// True when a point of `path` (from index `from`) lies in a forbidden cell of the
    /// current grid (an obstacle appeared on it since it was planned), ignoring the cells
    /// within robot_radius of `robot`.
    bool blocked(const std::vector<Eigen::Vector2d>& path, std::size_t from,
                 const Eigen::Vector2d& robot) const;

    /// Points along `path` every waypoint_spacing metres (path length), the last one its end.
    std::vector<Eigen::Vector2d> waypoints(const std::vector<Eigen::Vector2d>& path) const;

    /// Distance [m] of a cell to the nearest obstacle cell (after setGrid).
    float obstacleDistance(long cell) const { return distance_[static_cast<std::size_t>(cell)]; }
    /// Cells A* expanded in the last plan().
    std::size_t expanded() const { return expanded_; }

  private:
    long cellOf(const Eigen::Vector2d& p) const;
    /// Cost factor of entering the cell (< 0: forbidden).
    float cellCost(long cell) const;

    GridPlannerOptions options_;
    GridGeometry geometry_;
    int sx_ = 0, sy_ = 0;
    std::vector<CellState> states_;
    std::vector<float> slopes_;
    std::vector<float> distance_;  // [m] to the nearest obstacle cell
    std::vector<float> g_;         // A* scratch
    std::vector<int32_t> parent_;
    std::vector<uint8_t> closed_;
    std::size_t expanded_ = 0;
};

}  // namespace travel
