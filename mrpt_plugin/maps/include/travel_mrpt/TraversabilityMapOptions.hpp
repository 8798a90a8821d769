// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Options of CTraversabilityMap: the grid geometry, the OctoMap, the fusion rules, and the
// TRAVEL filter (TravelFilterOptions: `preset`, every libtravel parameter, the filter keys).
// Read from an ini section; in a CMultiMetricMap .ini both sections of the map,
// [<prefix>_creationOpts] and [<prefix>_insertOpts], accept every key below (applied in that
// order: put the geometry in the first and the rest in the second by convention). A key that is
// neither a map key, a filter key nor a libtravel parameter is an error naming it and the section.
//
// Map keys (units):
//   min_x, max_x, min_y, max_y  [m]    grid extent, world frame (default -20..20 x -20..20)
//   resolution                  [m]    grid cell side (0.2)
//   octomap_resolution          [m]    OctoMap voxel side (0.2)
//   octomap_prob_hit, octomap_prob_miss  [0..1] OctoMap sensor model (0.7, 0.4)
//   max_ray_length              [m]    rays longer than this carve free space up to this
//                                      length only and mark nothing occupied (30)
//   ray_stride                  [-]    carve free space along every n-th ground ray (2; obstacle
//                                      rays are always cast)
//   obstacle_min_height         [m]    non-ground points at least this high above the local
//                                      ground are obstacles (0.25)
//   obstacle_max_height         [m]    ... and, for the 2-D grid, at most this high (2.0; the
//                                      OctoMap keeps higher ones: overhangs)
//   logodds_obstacle, logodds_ground   per-frame log-odds increments of a cell (0.85, -0.4)
//   logodds_min, logodds_max           clamps (-2, 3.5)
//   obstacle_threshold, free_threshold log-odds above: obstacle; below: ground (0.5, -0.3)
//   min_obstacle_points         [-]    obstacle points a cell needs in one frame (2)
//   min_step_points             [-]    ground points a cell needs in one frame for a step (4)
//   max_step_height             [m]    larger step inside a cell: not traversable (0.1)
//   max_slope_deg               [deg]  steeper terrain model: not traversable (20)
//   max_neighbour_step          [m]    larger step between neighbouring cells' fused ground
//                                      heights: not traversable (0 = off); when on, each
//                                      frame's ground is levelled against the map first
//   (max_slope_deg is also a libtravel parameter name: in these sections it is the map's.)
#pragma once

#include <mrpt/config/CLoadableOptions.h>

#include <string>
#include <vector>

#include "travel/traversability/TraversabilityGrid.hpp"
#include "travel_mrpt/TravelFilterOptions.hpp"

namespace travel_mrpt {

// The grid is libtravel's (travel::traversability); MRPT code keeps naming it from here.
using travel::CellState;
using travel::GridFusionParams;
using travel::GridGeometry;
using travel::TraversabilityGrid;

struct TraversabilityMapOptions : public mrpt::config::CLoadableOptions {
    GridGeometry geometry;
    GridFusionParams fusion;
    double octomap_resolution = 0.2;    ///< [m]
    double octomap_prob_hit = 0.7;      ///< probability of occupancy of a hit
    double octomap_prob_miss = 0.4;     ///< probability of occupancy of a traversed voxel
    double max_ray_length = 30.0;       ///< [m]
    int ray_stride = 2;                 ///< every n-th ground ray carves free space
    double obstacle_min_height = 0.25;  ///< [m] above the local ground
    double obstacle_max_height = 2.0;   ///< [m] above the local ground (2-D grid only)
    TravelFilterOptions travel;

    /// The map's own keys (not TRAVEL's).
    static const std::vector<std::string>& mapKeys();

    /// Applies every key of `section` on top of the current values (see the file comment).
    /// Throws travel::ConfigError naming the section and the key.
    void loadFromConfigFile(const mrpt::config::CConfigFileBase& source,
                            const std::string& section) override;
    /// Writes every map key, then TravelFilterOptions' keys.
    void saveToConfigFile(mrpt::config::CConfigFileBase& target,
                          const std::string& section) const override;
    /// Throws travel::ConfigError naming the offending key.
    void validate() const;
};

}  // namespace travel_mrpt
