// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/TerrainModel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace travel {

float TerrainModel::groundSlopeDeg(float x, float y) const {
    const int node = nodeAt(x, y);
    const std::optional<GroundPlane> ground =
        node >= 0 && usable() ? groundPlane(node) : std::nullopt;
    if (!ground) return std::numeric_limits<float>::quiet_NaN();
    return std::acos(std::clamp(ground->normal.z(), -1.f, 1.f)) * 57.2957795f;
}

float TerrainModel::heightAboveGround(float x, float y, float z) const {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const int node = nodeAt(x, y);
    if (node < 0 || !usable()) return nan;
    const int side = cells_per_side, cell = node / 4;
    const int cx = cell % side, cy = cell / side;
    static constexpr int kAround[5][2] = {{0, 0}, {1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    float h = std::numeric_limits<float>::infinity();
    for (const auto& d : kAround) {
        const int ix = cx + d[0], iy = cy + d[1];
        if (ix < 0 || iy < 0 || ix >= side || iy >= side) continue;
        for (int tri = 0; tri < 4; ++tri)
            if (const std::optional<GroundPlane> ground = groundPlane(4 * (iy * side + ix) + tri))
                h = std::min(h, z - ground->heightAt(x, y));
    }
    return std::isfinite(h) ? h : nan;
}

float TerrainModel::stepBetween(int a, int b, float min_spread) const {
    const TriNode &na = nodes[static_cast<std::size_t>(a)],
                  &nb = nodes[static_cast<std::size_t>(b)];
    const float min_l2 = min_spread * min_spread;
    const auto comparable = [&](const TriNode& n) {
        return n.traversable && n.node_class == NodeClass::Terrain && n.eigenvalues.y() >= min_l2;
    };
    if (!comparable(na) || !comparable(nb)) return 0.f;
    // The shared edge: the two lattice corners both triangles have.
    Eigen::Vector2f edge_sum(0.f, 0.f);
    int shared = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (cornerOnLattice(a, i) == cornerOnLattice(b, j)) {
                const std::array<int, 2> l = cornerOnLattice(a, i);
                edge_sum += latticeXY(l[0], l[1]);
                ++shared;
            }
    if (shared != 2) return 0.f;
    const Eigen::Vector2f mid = 0.5f * edge_sum;
    // A plane is only known where its points are; the seen-ground measures (the other node's
    // plane at this node's mean) veto steps that only an extrapolated tilt makes.
    const float edge = planeHeightAt(na.normal, na.d, mid.x(), mid.y()) -
                       planeHeightAt(nb.normal, nb.d, mid.x(), mid.y());
    const float a_over_b = na.mean.z() - planeHeightAt(nb.normal, nb.d, na.mean.x(), na.mean.y());
    const float b_under_a = planeHeightAt(na.normal, na.d, nb.mean.x(), nb.mean.y()) - nb.mean.z();
    if (edge > 0.f) return std::max(0.f, std::min({edge, a_over_b, b_under_a}));
    if (edge < 0.f) return -std::max(0.f, std::min({-edge, -a_over_b, -b_under_a}));
    return 0.f;
}

}  // namespace travel
