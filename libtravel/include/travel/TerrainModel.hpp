// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The terrain model of one frame: one entry per tri-grid node (paper Sec. III-B..D).
// Coordinates are in the aligned frame: origin at the sensor, x/y horizontal (vehicle heading
// for x), z up against gravity. Ground under the vehicle is near z = -sensor_height.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace travel {

/// Node class of the node-wise terrain model (paper Sec. III-B).
enum class NodeClass : uint8_t {
    Empty = 0,     ///< no points
    Unknown = 1,   ///< fewer than node_min_points points: no reliable plane
    Terrain = 2,   ///< plane normal within max_slope of vertical
    Obstacle = 3,  ///< plane too steep
};

struct TriNode {
    // Points of this node are [begin, begin + count) of TriGridField's sorted order.
    uint32_t begin = 0;
    uint32_t count = 0;

    NodeClass node_class = NodeClass::Empty;
    /// Plane of the node-wise model (PCA): normal s (unit, z >= 0), mean m, offset d = -s.m.
    Eigen::Vector3f normal{0.f, 0.f, 1.f};
    Eigen::Vector3f mean{0.f, 0.f, 0.f};
    float d = 0.f;
    /// Eigenvalues of the last PCA, l1 >= l2 >= l3, and the paper's weight (eq. 1).
    Eigen::Vector3f eigenvalues{0.f, 0.f, 0.f};
    float weight = 0.f;
    /// Lowest point representative (mean z of the lowest points).
    float lpr = 0.f;

    /// Result of the breadth-first traversable graph search (Sec. III-C).
    bool reached = false;
    /// Search component id (0 = first search from the sensor seed, k > 0 = k-th re-seed).
    int16_t component = -1;

    /// TTMF (Sec. III-D): corner heights (NaN when no traversable node voted) and the refitted
    /// plane through them. 'traversable' is the final decision used for point labels.
    Eigen::Vector3f corner_z{0.f, 0.f, 0.f};
    bool refitted = false;
    Eigen::Vector3f refit_normal{0.f, 0.f, 1.f};
    Eigen::Vector3f refit_mean{0.f, 0.f, 0.f};
    float refit_d = 0.f;
    bool traversable = false;
};

/// z of the plane s.p + d = 0 above (x, y). Callers guarantee s.z > 0 (terrain planes).
inline float planeHeightAt(const Eigen::Vector3f& s, float d, float x, float y) {
    return -(s.x() * x + s.y() * y + d) / s.z();
}

struct TerrainModel {
    float resolution = 0.f;      ///< r [m]
    int cells_per_side = 0;      ///< the grid is cells_per_side x cells_per_side cells
    float origin_xy = 0.f;       ///< x and y of the grid's lower-left corner (= -R)
    std::vector<TriNode> nodes;  ///< 4 per cell; index = 4 * (iy * cells_per_side + ix) + tri
    int seed_node = -1;          ///< start node of the first search (-1: no terrain near sensor)
    int num_components = 0;      ///< searches run (first + re-seeds)

    /// Triangle k of a cell: 0 = +x side (east), 1 = +y (north), 2 = -x (west), 3 = -y (south).
    /// Its corners are the cell centre and the two cell corners of that side.
    Eigen::Vector2f cellCenter(int cell) const {
        const int ix = cell % cells_per_side, iy = cell / cells_per_side;
        return {origin_xy + (ix + 0.5f) * resolution, origin_xy + (iy + 0.5f) * resolution};
    }
};

}  // namespace travel
