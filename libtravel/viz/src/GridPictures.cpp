// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/viz/GridPictures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace travel::viz {

Raster traversabilityRaster(const TraversabilityGrid& grid, const GridFusionParams& fusion,
                            bool north_up) {
    Raster raster;
    raster.reset(grid.sizeX(), grid.sizeY(), {45, 45, 45});  // never observed
    for (int iy = 0; iy < grid.sizeY(); ++iy)
        for (int ix = 0; ix < grid.sizeX(); ++ix) {
            const int v = north_up ? grid.sizeY() - 1 - iy : iy;
            const long c = grid.cellIndex(ix, iy);
            switch (grid.state(c, fusion)) {
                case CellState::Traversable:
                    raster.set(ix, v, {70, 175, 70});
                    break;
                case CellState::Obstacle:
                    raster.set(ix, v, {215, 45, 35});
                    break;
                case CellState::Unknown:
                    if (grid.observed(c)) raster.set(ix, v, {140, 140, 140});  // seen, undecided
                    break;
            }
        }
    return raster;
}

Raster heightRaster(const TraversabilityGrid& grid, double z_lo, double z_hi,
                    Rgb (*colourOf)(float t)) {
    if (!(z_lo < z_hi)) {
        z_lo = std::numeric_limits<double>::infinity(), z_hi = -z_lo;
        for (std::size_t c = 0; c < grid.cellCount(); ++c) {
            const float h = grid.groundHeight(long(c));
            if (std::isfinite(h))
                z_lo = std::min(z_lo, double(h)), z_hi = std::max(z_hi, double(h));
        }
        if (!(z_lo < z_hi)) z_lo = 0, z_hi = 1;
    }
    Raster raster;
    raster.reset(grid.sizeX(), grid.sizeY(), {0, 0, 0});  // no ground
    for (int iy = 0; iy < grid.sizeY(); ++iy)
        for (int ix = 0; ix < grid.sizeX(); ++ix) {
            const float h = grid.groundHeight(grid.cellIndex(ix, iy));
            if (!std::isfinite(h)) continue;
            const float t = float(std::clamp((h - z_lo) / (z_hi - z_lo), 0.0, 1.0));
            raster.set(ix, grid.sizeY() - 1 - iy, colourOf(t));
        }
    return raster;
}

Raster enlarge(const Raster& raster, int factor) {
    factor = std::max(1, factor);
    Raster big;
    big.reset(raster.width * factor, raster.height * factor, {0, 0, 0});
    for (int v = 0; v < big.height; ++v)
        for (int u = 0; u < big.width; ++u) big.set(u, v, raster.at(u / factor, v / factor));
    return big;
}

}  // namespace travel::viz
