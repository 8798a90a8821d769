// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// From the configuration sections (travel/Config.hpp, where every key is declared once with its
// default, unit, range and documentation) to the structs the traversability stages take. Field
// for field, same names except map.max_traversable_slope_deg -> GridFusionParams::max_slope_deg
// (travel.max_slope_deg is TRAVEL's terrain rule, a different one).
#pragma once

#include "travel/Config.hpp"
#include "travel/traversability/TravelObstacles.hpp"
#include "travel/traversability/TraversabilityGrid.hpp"

namespace travel {

inline GridGeometry gridGeometry(const MapSection& m) {
    return {m.min_x, m.max_x, m.min_y, m.max_y, m.resolution};
}

inline GridFusionParams gridFusionParams(const MapSection& m) {
    GridFusionParams f;
    f.logodds_obstacle = m.logodds_obstacle;
    f.logodds_ground = m.logodds_ground;
    f.logodds_min = m.logodds_min;
    f.logodds_max = m.logodds_max;
    f.obstacle_threshold = m.obstacle_threshold;
    f.free_threshold = m.free_threshold;
    f.min_obstacle_points = m.min_obstacle_points;
    f.min_step_points = m.min_step_points;
    f.max_step_height = m.max_step_height;
    f.max_slope_deg = m.max_traversable_slope_deg;
    f.max_neighbour_step = m.max_neighbour_step;
    return f;
}

inline TravelObstacleOptions travelObstacleOptions(const NavSection& n) {
    TravelObstacleOptions o;
    o.max_step_height = n.max_step_height;
    o.max_height = n.max_height;
    o.report_floor = n.report_floor;
    o.ground_search_radius = n.ground_search_radius;
    o.step_min_spread = n.step_min_spread;
    return o;
}

}  // namespace travel
