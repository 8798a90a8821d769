// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/Params.hpp"

#include <algorithm>
#include <cmath>
#include <locale>
#include <sstream>
#include <string>
#include <tuple>
#include <type_traits>

#include "travel/Config.hpp"
#include "travel/ConfigFields.hpp"
#include "travel/Errors.hpp"
#include "travel/RangeImage.hpp"
#include "travel/TerrainModel.hpp"

namespace travel {

namespace {

// Messages only: the classic locale keeps '.' as the decimal point whatever the app set.
template <class T>
std::string formatForMessage(T value) {
    std::ostringstream out;
    out.imbue(std::locale::classic());
    if constexpr (std::is_same_v<T, bool>) {
        out << (value ? "true" : "false");
    } else {
        out << value;
    }
    return out.str();
}

}  // namespace

void Params::validate() const {
    checkRanges(*this);

    if (!(min_range < max_range)) {
        throw ConfigError("min_range = " + formatForMessage(min_range) +
                          " m must be smaller than max_range = " + formatForMessage(max_range) +
                          " m");
    }

    for (const auto& [axis, lo, hi] : {std::tuple{"x", self_box_min_x, self_box_max_x},
                                       std::tuple{"y", self_box_min_y, self_box_max_y},
                                       std::tuple{"z", self_box_min_z, self_box_max_z}}) {
        if (!(lo <= hi)) {
            throw ConfigError(std::string("self_box_min_") + axis + " = " + formatForMessage(lo) +
                              " m must not exceed self_box_max_" + axis + " = " +
                              formatForMessage(hi) + " m");
        }
    }

    if (!(min_elevation_deg < max_elevation_deg)) {
        throw ConfigError("min_elevation_deg = " + formatForMessage(min_elevation_deg) +
                          " deg must be smaller than max_elevation_deg = " +
                          formatForMessage(max_elevation_deg) + " deg");
    }
    if (min_cluster_size > max_cluster_size) {
        throw ConfigError(
            "min_cluster_size = " + formatForMessage(min_cluster_size) +
            " must not exceed max_cluster_size = " + formatForMessage(max_cluster_size));
    }

    // The range image's cell counters are cleared every frame, and the point buffers are sized
    // for beams x num_columns points when a pipeline is built: bounded like the grid (the
    // largest spinning LiDARs have 128 x 2048 = 262,144 cells).
    const double beams = std::max<double>(num_rings, elevationTableDeg(*this).size());
    if (beams * num_columns > kMaxRangeImageCells) {
        throw ConfigError("range image too large: " + formatForMessage(beams) + " beams x " +
                          formatForMessage(num_columns) +
                          " num_columns = " + formatForMessage(beams * num_columns) +
                          " cells, more than " + formatForMessage(kMaxRangeImageCells) +
                          "; reduce num_columns (or num_rings)");
    }

    // The grid covers [-max_range, max_range] in x and y; a partial cell still costs a cell.
    // Exactly what TriGridField::configure builds (about 2 * ceil(R / r) cells per side).
    const double cells_per_side = 2.0 * TriGridGeometry::halfCellsFor(max_range, tgf_resolution);
    if (cells_per_side > static_cast<double>(max_grid_cells_per_side)) {
        throw ConfigError("tri-grid too large: 2 * max_range / tgf_resolution = 2 * " +
                          formatForMessage(max_range) + " / " + formatForMessage(tgf_resolution) +
                          " needs " + formatForMessage(cells_per_side) +
                          " cells per side, more than max_grid_cells_per_side = " +
                          formatForMessage(max_grid_cells_per_side) +
                          "; increase tgf_resolution, reduce max_range or raise "
                          "max_grid_cells_per_side");
    }
}

}  // namespace travel
