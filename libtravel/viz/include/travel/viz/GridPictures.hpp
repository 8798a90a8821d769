// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Pictures of the fused traversability grid (travel::TraversabilityGrid), one pixel per cell,
// +x to the right. The MRPT layer copies them into CImages (PNG exports, the map's texture).
#pragma once

#include "travel/traversability/TraversabilityGrid.hpp"
#include "travel/viz/Raster.hpp"

namespace travel::viz {

/// Traversable green, obstacle red, observed but undecided grey, never observed dark grey.
/// north_up: row 0 = max_y (pictures); else row 0 = min_y (textures).
Raster traversabilityRaster(const TraversabilityGrid& grid, const GridFusionParams& fusion,
                            bool north_up = true);

/// Ground heights, north up: colourOf(t) with t = (h - z_lo) / (z_hi - z_lo) clamped to [0, 1]
/// (when z_lo >= z_hi: over the observed heights, else [0, 1]); black where no ground.
Raster heightRaster(const TraversabilityGrid& grid, double z_lo, double z_hi,
                    Rgb (*colourOf)(float t));

/// Nearest-neighbour enlargement so that small grids are visible (factor < 1 counts as 1).
Raster enlarge(const Raster& raster, int factor);

}  // namespace travel::viz
