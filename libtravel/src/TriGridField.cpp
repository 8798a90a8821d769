// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/TriGridField.hpp"

#include <algorithm>
#include <cmath>

namespace travel {

void TriGridField::configure(const Params& params) {
    const float r = static_cast<float>(params.tgf_resolution);
    const int half = static_cast<int>(std::ceil(params.max_range / params.tgf_resolution));
    const int n = 2 * std::max(half, 1);
    if (r == resolution_ && n == cells_per_side_) return;
    resolution_ = r;
    cells_per_side_ = n;
    origin_ = -half * r;

    const int num_nodes = 4 * n * n;
    const int lattice = 2 * n + 1;
    // Triangle k's corners on the half-cell lattice: the cell centre (2ix+1, 2iy+1) and the
    // two cell corners of its side (east, north, west, south).
    static constexpr int kCornerOffsets[4][2][2] = {
        {{2, 0}, {2, 2}}, {{2, 2}, {0, 2}}, {{0, 2}, {0, 0}}, {{0, 0}, {2, 0}}};
    vertices_.resize(3 * num_nodes);
    for (int cell = 0; cell < n * n; ++cell) {
        const int ix = cell % n, iy = cell / n;
        for (int k = 0; k < 4; ++k) {
            const int node = 4 * cell + k;
            vertices_[3 * node] = (2 * iy + 1) * lattice + (2 * ix + 1);
            for (int c = 0; c < 2; ++c) {
                vertices_[3 * node + 1 + c] = (2 * iy + kCornerOffsets[k][c][1]) * lattice +
                                              (2 * ix + kCornerOffsets[k][c][0]);
            }
        }
    }
    // Neighbours = triangles of the 3x3 surrounding cells sharing at least one vertex.
    neighbours_.assign(num_nodes, Neighbours{});
    for (int node = 0; node < num_nodes; ++node) {
        const int cell = node / 4, ix = cell % n, iy = cell / n;
        Neighbours& nb = neighbours_[node];
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                const int jx = ix + dx, jy = iy + dy;
                if (jx < 0 || jy < 0 || jx >= n || jy >= n) continue;
                for (int k = 0; k < 4; ++k) {
                    const int other = 4 * (jy * n + jx) + k;
                    if (other == node) continue;
                    bool shares = false;
                    for (int a = 0; a < 3 && !shares; ++a)
                        for (int b = 0; b < 3 && !shares; ++b)
                            shares = vertices_[3 * node + a] == vertices_[3 * other + b];
                    if (shares) nb.ids[nb.count++] = other;
                }
            }
        }
    }
}

void TriGridField::vertexXY(int vertex, float& x, float& y) const {
    const int lattice = 2 * cells_per_side_ + 1;
    x = origin_ + 0.5f * resolution_ * static_cast<float>(vertex % lattice);
    y = origin_ + 0.5f * resolution_ * static_cast<float>(vertex / lattice);
}

void TriGridField::embed(const AlignedCloud& cloud, TerrainModel& model) {
    const int num_nodes = numNodes();
    model.resolution = resolution_;
    model.cells_per_side = cells_per_side_;
    model.origin_xy = origin_;
    model.nodes.assign(num_nodes, TriNode{});

    // Counting sort by node: pass 1 counts, pass 2 scatters into contiguous slices.
    const std::size_t n = cloud.x.size();
    point_node_.resize(n);
    node_start_.assign(num_nodes + 1, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const int node = cloud.valid[i] ? nodeOf(cloud.x[i], cloud.y[i]) : -1;
        point_node_[i] = node;
        if (node >= 0) ++node_start_[node + 1];
    }
    for (int k = 0; k < num_nodes; ++k) node_start_[k + 1] += node_start_[k];
    const uint32_t total = node_start_[num_nodes];
    sx_.resize(total), sy_.resize(total), sz_.resize(total), order_.resize(total);
    for (int k = 0; k < num_nodes; ++k) {
        model.nodes[k].begin = node_start_[k];
        model.nodes[k].count = node_start_[k + 1] - node_start_[k];
    }
    for (std::size_t i = 0; i < n; ++i) {
        const int node = point_node_[i];
        if (node < 0) continue;
        const uint32_t slot = node_start_[node]++;
        sx_[slot] = cloud.x[i], sy_[slot] = cloud.y[i], sz_[slot] = cloud.z[i];
        order_[slot] = static_cast<uint32_t>(i);
    }
}

}  // namespace travel
