// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The terrain model of one frame: one entry per tri-grid node (paper Sec. III-B..D).
// Coordinates are in the aligned frame: origin at the sensor, x/y horizontal (vehicle heading
// for x), z up against gravity. Ground under the vehicle is near z = -sensor_height.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
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

/// A ground plane s.p + d = 0 (s unit, s.z > 0).
struct GroundPlane {
    Eigen::Vector3f normal{0.f, 0.f, 1.f};
    float d = 0.f;
    float heightAt(float x, float y) const { return planeHeightAt(normal, d, x, y); }
};

/// Triangle k of a cell: 0 = +x side (east), 1 = +y (north), 2 = -x (west), 3 = -y (south).
/// Its corners are the cell centre and the two cell corners of that side, counter-clockwise;
/// kTriangleSideCorners[k][c] = (x, y) of side corner c as 0/1 steps from the cell's lower-left
/// corner. The one corner table of the tri-grid (TriGridField's vertex lattice uses it too).
inline constexpr int kTriangleSideCorners[4][2][2] = {
    {{1, 0}, {1, 1}}, {{1, 1}, {0, 1}}, {{0, 1}, {0, 0}}, {{0, 0}, {1, 0}}};

/// Which triangle of cell (ix, iy) = (int(gx), int(gy)) holds grid coordinates (gx, gy)
/// (metres / r from the grid's lower-left corner, inside the grid): compare the offsets from
/// the cell centre (the diagonals are |u| = |v|). Written as selects, without branches, so that
/// TriGridField::embed's loop over all points vectorises; nodeAt() uses the same code.
inline int triangleNodeOfGridCoords(float gx, float gy, int cells_per_side) {
    const int ix = static_cast<int>(gx), iy = static_cast<int>(gy);
    const float u = gx - (static_cast<float>(ix) + 0.5f);
    const float v = gy - (static_cast<float>(iy) + 0.5f);
    // The larger offset (|u| >= |v|: the +-x triangles) and its sign pick the triangle; as one
    // blend and one compare, embed's loop needs a few instructions a point.
    const bool horizontal = std::fabs(u) >= std::fabs(v);
    const float along = horizontal ? u : v;
    return 4 * (iy * cells_per_side + ix) + (horizontal ? 0 : 1) + (along < 0.f ? 2 : 0);
}

/// Geometry of the tri-grid (paper Sec. III-B): a square of cells_per_side^2 cells of side r,
/// lower-left corner at (origin_xy, origin_xy), 4 triangular nodes per cell,
/// node index = 4 * (iy * cells_per_side + ix) + triangle.
struct TriGridGeometry {
    float resolution = 0.f;  ///< r [m]
    int cells_per_side = 0;  ///< the grid is cells_per_side x cells_per_side cells
    float origin_xy = 0.f;   ///< x and y of the grid's lower-left corner (= -R)

    bool hasCells() const { return cells_per_side > 0 && resolution > 0.f; }

    /// Cells from the sensor to the grid's edge for the range window [-max_range, max_range]
    /// [m] and cells of `resolution` [m]: ceil(max_range / r), and one more when the float
    /// extent half * float(r) falls short of float(max_range) (r = 0.9, R = 81: 80.9999978), so
    /// that every valid point is in a node. The grid is 2 * half cells per side.
    static int halfCellsFor(double max_range, double resolution) {
        const float r = static_cast<float>(resolution), range = static_cast<float>(max_range);
        int half = std::max(1, static_cast<int>(std::ceil(max_range / resolution)));
        while (static_cast<float>(half) * r < range) ++half;
        return half;
    }
    int numNodes() const { return 4 * cells_per_side * cells_per_side; }

    Eigen::Vector2f cellCenter(int cell) const {
        const int ix = cell % cells_per_side, iy = cell / cells_per_side;
        return {origin_xy + (static_cast<float>(ix) + 0.5f) * resolution,
                origin_xy + (static_cast<float>(iy) + 0.5f) * resolution};
    }

    /// The same grid (resolution, size and origin).
    bool sameGrid(const TriGridGeometry& other) const {
        return resolution == other.resolution && cells_per_side == other.cells_per_side &&
               origin_xy == other.origin_xy;
    }

    /// The grid is closed, [origin, origin + n r] in x and y like the range window
    /// [-max_range, max_range], so that a valid point at exactly +max_range is in the last cell.
    /// edgeGridCoord(): the grid coordinate ((x - origin) * (1 / r), as every point's) of the far
    /// edge; rounding is monotonic, so no x up to the edge maps above it, though it may be a
    /// float step above n when 1 / r is inexact (r = 7, n r = 84: 24.0000019). Plus a few float
    /// steps: a point checked against max_range in 3-D and then rotated may round a step past.
    float edgeGridCoord() const {
        const float upper = origin_xy + static_cast<float>(cells_per_side) * resolution;
        return (upper - origin_xy) * (1.f / resolution) *
               (1.f + 8.f * std::numeric_limits<float>::epsilon());
    }
    /// The largest grid coordinate inside the last cell: points between it and edgeGridCoord()
    /// are moved there.
    /// (std::nextafter(n, 0), n >= 1: the bits of n less one, inline; nextafterf is a libm call,
    /// and nodeAt runs for every point of a frame fused into a map.)
    float lastGridCoord() const {
        const float n = static_cast<float>(cells_per_side);
        uint32_t bits;
        std::memcpy(&bits, &n, sizeof bits);
        --bits;
        float last;
        std::memcpy(&last, &bits, sizeof last);
        return last;
    }

    /// Node holding (x, y), or -1 outside the grid (also for NaN and huge coordinates).
    int nodeAt(float x, float y) const {
        if (!hasCells()) return -1;
        const float inv_r = 1.f / resolution;
        const float gx = (x - origin_xy) * inv_r, gy = (y - origin_xy) * inv_r;
        // Bounds before the float->int conversion (huge values would be undefined).
        const float limit = edgeGridCoord();
        if (!(gx >= 0.f && gy >= 0.f && gx <= limit && gy <= limit)) return -1;
        const float last = lastGridCoord();
        return triangleNodeOfGridCoords(gx < last ? gx : last, gy < last ? gy : last,
                                        cells_per_side);
    }

    /// Corner k (0 = cell centre, 1, 2 = the side's cell corners, counter-clockwise) of a
    /// node's triangle on the lattice of half-cell steps: ((2n+1) x (2n+1) points, cell corners
    /// at even coordinates, cell centres at odd ones). Neighbouring nodes share lattice points
    /// exactly, where float corners computed from two cells could differ in the last bit.
    std::array<int, 2> cornerOnLattice(int node, int k) const {
        const int cell = node / 4, tri = node % 4;
        const int ix = cell % cells_per_side, iy = cell / cells_per_side;
        if (k == 0) return {2 * ix + 1, 2 * iy + 1};
        return {2 * ix + 2 * kTriangleSideCorners[tri][k - 1][0],
                2 * iy + 2 * kTriangleSideCorners[tri][k - 1][1]};
    }
    /// xy of a lattice point.
    Eigen::Vector2f latticeXY(int lx, int ly) const {
        return {origin_xy + 0.5f * resolution * static_cast<float>(lx),
                origin_xy + 0.5f * resolution * static_cast<float>(ly)};
    }
    /// xy of the 3 corners of a node's triangle (cell centre first, counter-clockwise).
    std::array<Eigen::Vector2f, 3> triangleCorners(int node) const {
        std::array<Eigen::Vector2f, 3> xy;
        for (int k = 0; k < 3; ++k) {
            const std::array<int, 2> l = cornerOnLattice(node, k);
            xy[static_cast<std::size_t>(k)] = latticeXY(l[0], l[1]);
        }
        return xy;
    }
};

/// nodeAt() for a loop over every point of a frame: branch-free, so that the loop vectorises,
/// and numNodes() (`outside`) instead of -1 off the grid and for invalid points. A copy of the
/// geometry's values in the loop's registers (a member function would reread them after every
/// store of the loop). The same floats and the same triangle as nodeAt().
struct NodeLocator {
    float inv_r, origin, limit, last;
    int side;
    uint32_t outside;

    explicit NodeLocator(const TriGridGeometry& grid)
        : inv_r(1.f / grid.resolution),
          origin(grid.origin_xy),
          limit(grid.edgeGridCoord()),
          last(grid.lastGridCoord()),
          side(grid.cells_per_side),
          outside(static_cast<uint32_t>(grid.numNodes())) {}

    uint32_t operator()(float x, float y, bool valid) const {
        // Bitwise & of the bools: GCC leaves && as branches here, and the loop unvectorised.
        const float gx = (x - origin) * inv_r, gy = (y - origin) * inv_r;
        const bool in_x = (gx >= 0.f) & (gx <= limit), in_y = (gy >= 0.f) & (gy <= limit);
        // Outside points are moved to 0 so the float->int conversion stays defined (NaN, huge
        // values); inside points keep their exact position, the far edge its last cell's.
        // Values, not std::min's references: GCC does not if-convert a select of addresses, and
        // the loop stayed scalar (preprocess 8x slower).
        const float ex = gx < last ? gx : last, ey = gy < last ? gy : last;
        const float cx = in_x ? ex : 0.f, cy = in_y ? ey : 0.f;
        const int node = triangleNodeOfGridCoords(cx, cy, side);
        return (valid & in_x & in_y) ? static_cast<uint32_t>(node) : outside;
    }
};

struct TerrainModel : TriGridGeometry {
    std::vector<TriNode> nodes;  ///< 4 per cell; index = 4 * (iy * cells_per_side + ix) + tri
    int seed_node = -1;          ///< start node of the first search (-1: no terrain near sensor)
    int num_components = 0;      ///< searches run (first + re-seeds)

    /// True when `nodes` matches the geometry (a model read from a file may not).
    bool usable() const {
        return hasCells() && nodes.size() == static_cast<std::size_t>(numNodes());
    }

    /// THE ground rule: a node has ground iff TTMF made it traversable, and its ground is the
    /// plane its points were labelled against (paper eq. 5): TTMF's refitted plane, or the
    /// node's own plane when TTMF is off (TerrainModelFitting copies it into refit_*). Every
    /// point labelled Ground lies within ground_dist of this plane, so a map or navigator
    /// measuring heights against any other plane could call a point "ground" and "an obstacle
    /// above the ground" at once (with label_with_node_plane, points of clear nodes, and of
    /// reached nodes with nothing tall within clearance_radius, also within ground_dist of their
    /// own or a clear neighbour's plane: verges up to about 0.3 m above this one,
    /// GroundLabelling.cpp). Its normal is within max_slope of vertical.
    std::optional<GroundPlane> groundPlane(int node) const {
        const TriNode& n = nodes[static_cast<std::size_t>(node)];
        if (!n.traversable) return std::nullopt;
        return GroundPlane{n.refit_normal, n.refit_d};
    }

    /// Height of (x, y, z) above the local ground: the lowest of its heights over the ground
    /// planes of the nodes of its cell and of the 4 cells sharing an edge with it. The lowest,
    /// because where the terrain bends (the foot of a ramp, a kerb) one node's plane
    /// extrapolated across the bend lifts the ground; a point standing on the upper level is
    /// measured from that level. NaN outside the grid or when none of these nodes has ground:
    /// the caller's own fallback (fused map ground, robot base plane, sensor height) follows.
    float heightAboveGround(float x, float y, float z) const;

    /// Slope [deg] of the ground under (x, y): of groundPlane() of the node holding it; NaN
    /// outside the grid or where that node has no ground.
    float groundSlopeDeg(float x, float y) const;

    /// Step of node a over node b at their shared edge, from each node's OWN (node-wise PCA)
    /// plane: TTMF smooths steps away. The step must show three times: a's plane above b's at
    /// the midpoint of the shared edge, a's mean above b's plane, and b's mean below a's plane;
    /// the result is the smallest of the three (> 0: a is higher, < 0: b is higher by -result,
    /// 0: no consistent step, no shared edge, or either node is not traversable terrain of its
    /// own (NodeClass::Terrain) whose points spread at least min_spread [m, std. dev.] in their
    /// second direction: a plane fitted to one ring's arc or a small patch has an unknown tilt).
    float stepBetween(int a, int b, float min_spread) const;
};

}  // namespace travel
