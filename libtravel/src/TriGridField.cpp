// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/TriGridField.hpp"

#include <algorithm>
#include <cmath>

#include "Prefault.hpp"

namespace travel {

void TriGridField::configure(const Params& params) {
    const float r = static_cast<float>(params.tgf_resolution);
    const int half = static_cast<int>(std::ceil(params.max_range / params.tgf_resolution));
    const int n = 2 * std::max(half, 1);
    if (r == geometry_.resolution && n == geometry_.cells_per_side) return;
    geometry_.resolution = r;
    geometry_.cells_per_side = n;
    geometry_.origin_xy = -half * r;

    const int num_nodes = 4 * n * n;
    const int lattice = 2 * n + 1;
    vertices_.resize(3 * num_nodes);
    for (int node = 0; node < num_nodes; ++node)
        for (int k = 0; k < 3; ++k) {
            const std::array<int, 2> l = geometry_.cornerOnLattice(node, k);
            vertices_[3 * node + k] = l[1] * lattice + l[0];
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

void TriGridField::reserve(std::size_t points) {
    detail::prefault(point_node_, points);
    detail::prefault(sx_, points), detail::prefault(sy_, points), detail::prefault(sz_, points);
    detail::prefault(order_, points);
}

void TriGridField::vertexXY(int vertex, float& x, float& y) const {
    const int lattice = 2 * geometry_.cells_per_side + 1;
    const Eigen::Vector2f xy = geometry_.latticeXY(vertex % lattice, vertex / lattice);
    x = xy.x(), y = xy.y();
}

void TriGridField::embed(const AlignedCloud& cloud, TerrainModel& model) {
    const int num_nodes = numNodes();
    static_cast<TriGridGeometry&>(model) = geometry_;
    model.nodes.assign(num_nodes, TriNode{});

    // Counting sort by node: pass 1 counts, pass 2 scatters into contiguous slices.
    // Sensors deliver long runs of points in the same node, so counts and slots are kept in
    // registers for the current run and flushed when the node changes: a plain ++count[node]
    // per point would chain every increment through memory. Raw pointers let the compiler keep
    // everything else in registers too (vector members could alias the written data).
    const std::size_t n = cloud.x.size();
    point_node_.resize(n);
    node_start_.assign(num_nodes + 1, 0);
    const float* px = cloud.x.data();
    const float* py = cloud.y.data();
    const float* pz = cloud.z.data();
    const uint8_t* valid = cloud.valid.data();
    int32_t* point_node = point_node_.data();
    uint32_t* start = node_start_.data();
    // Node of every point: the same code as nodeOf() (triangleNodeOfGridCoords, selects that
    // vectorise with -fno-trapping-math, see CMakeLists). Coordinates outside the grid are
    // replaced before the float->int conversion, so NaN and huge values stay defined.
    const float inv_r = 1.f / geometry_.resolution, origin = geometry_.origin_xy;
    const float limit = static_cast<float>(geometry_.cells_per_side);
    const int side = geometry_.cells_per_side;
    for (std::size_t i = 0; i < n; ++i) {
        const float gx = (px[i] - origin) * inv_r, gy = (py[i] - origin) * inv_r;
        const int inside = (valid[i] != 0 ? 1 : 0) & (gx >= 0.f ? 1 : 0) & (gy >= 0.f ? 1 : 0) &
                           (gx < limit ? 1 : 0) & (gy < limit ? 1 : 0);
        // Outside points (dropped below) are moved to 0 so the conversion stays defined;
        // inside points keep their exact position (same triangle as nodeOf()).
        const float cx = gx >= 0.f && gx < limit ? gx : 0.f;
        const float cy = gy >= 0.f && gy < limit ? gy : 0.f;
        const int node = triangleNodeOfGridCoords(cx, cy, side);
        point_node[i] = inside ? node : -1;
    }
    int run_node = -1;
    uint32_t run_length = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const int node = point_node[i];
        if (node != run_node) {
            if (run_node >= 0) start[run_node + 1] += run_length;
            run_node = node;
            run_length = 0;
        }
        ++run_length;
    }
    if (run_node >= 0) start[run_node + 1] += run_length;
    for (int k = 0; k < num_nodes; ++k) start[k + 1] += start[k];
    const uint32_t total = start[num_nodes];
    sx_.resize(total), sy_.resize(total), sz_.resize(total), order_.resize(total);
    for (int k = 0; k < num_nodes; ++k) {
        model.nodes[k].begin = start[k];
        model.nodes[k].count = start[k + 1] - start[k];
    }
    float* sx = sx_.data();
    float* sy = sy_.data();
    float* sz = sz_.data();
    uint32_t* order = order_.data();
    run_node = -1;
    uint32_t slot = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const int node = point_node[i];
        if (node < 0) continue;
        if (node != run_node) {
            if (run_node >= 0) start[run_node] = slot;
            run_node = node;
            slot = start[node];
        }
        sx[slot] = px[i], sy[slot] = py[i], sz[slot] = pz[i];
        order[slot] = static_cast<uint32_t>(i);
        ++slot;
    }
}

}  // namespace travel
