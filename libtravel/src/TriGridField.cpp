// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/TriGridField.hpp"

#include <algorithm>
#include <cmath>

#include "CpuDispatch.hpp"
#include "Prefault.hpp"

namespace travel {

void TriGridField::configure(const Params& params) {
    const float r = static_cast<float>(params.tgf_resolution);
    const int half = TriGridGeometry::halfCellsFor(params.max_range, params.tgf_resolution);
    const int n = 2 * half;
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
    // point_node_ is filled only for clouds without nodes (embed()): not prefaulted.
    detail::prefault(rank_, points);
    detail::prefault(occupied_, static_cast<std::size_t>(numNodes()));
    // One spare slot for the dropped points (embed's pass 2).
    detail::prefault(sx_, points + 1), detail::prefault(sy_, points + 1);
    detail::prefault(sz_, points + 1), detail::prefault(order_, points + 1);
}

void TriGridField::vertexXY(int vertex, float& x, float& y) const {
    const int lattice = 2 * geometry_.cells_per_side + 1;
    const Eigen::Vector2f xy = geometry_.latticeXY(vertex % lattice, vertex / lattice);
    x = xy.x(), y = xy.y();
}

TRAVEL_AVX2_CLONES
void TriGridField::embed(const AlignedCloud& cloud, TerrainModel& model) {
    const int num_nodes = numNodes();
    static_cast<TriGridGeometry&>(model) = geometry_;
    model.nodes.assign(num_nodes, TriNode{});

    // Counting sort by node, stable (a node's points keep their input order: the node fit's
    // float sums depend on it). Pass 1 gives every point its rank among the earlier points of
    // its node, pass 2 scatters it to start[node] + rank. Both passes are branch-free: the
    // sensors deliver runs of points in one node (~12 on an HDL-64E, ~4 on an OS-128), and a
    // branch on "node changed" mispredicts at every run end. Raw pointers let the compiler keep
    // everything in registers (vector members could alias the written data).
    const std::size_t n = cloud.x.size();
    rank_.resize(n);
    // Counts of the nodes, of the bucket `outside` (invalid and off-grid points, dropped) and
    // one cell never written (`unused`, see pass 1); then turned into the nodes' starts.
    const uint32_t outside = static_cast<uint32_t>(num_nodes), unused = outside + 1;
    node_start_.assign(num_nodes + 2, 0);
    // Node of every point (NodeLocator): preprocess() found them for this grid while the points
    // were in registers, else they are found here.
    const uint32_t* point_node = cloud.node.data();
    if (cloud.node.size() != n || !cloud.node_grid.sameGrid(geometry_)) {
        locateNodes(geometry_, cloud, point_node_);
        point_node = point_node_.data();
    }
    const float* px = cloud.x.data();
    const float* py = cloud.y.data();
    const float* pz = cloud.z.data();
    uint32_t* rank = rank_.data();
    uint32_t* start = node_start_.data();
    // Pass 1: rank = the previous point's rank + 1 within a run, else the node's count so far.
    // Within a run the count is read from `unused` instead: reading the count the previous
    // point has just stored would chain every point through a store-to-load forwarding. Masks
    // rather than ?:, which the compiler turns back into the branch that mispredicts.
    uint32_t run_node = unused, r = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const uint32_t node = point_node[i];
        const uint32_t same = 0u - static_cast<uint32_t>(node == run_node);  // all ones or 0
        const uint32_t count_so_far = start[(unused & same) | (node & ~same)];
        r = ((r + 1) & same) | (count_so_far & ~same);
        start[node] = r + 1;
        rank[i] = r;
        run_node = node;
    }
    // Counts to starts (exclusive prefix sum); start[outside] = number of embedded points.
    uint32_t sum = 0;
    for (uint32_t k = 0; k < outside; ++k) {
        const uint32_t count = start[k];
        start[k] = sum;
        sum += count;
    }
    start[outside] = sum;
    const uint32_t total = start[outside];
    // The nodes with points, in ascending order, listed without a branch (83 % of KITTI's nodes
    // are empty: the later stages then read no empty node's cache line), then their begin and
    // count (an empty node keeps begin = count = 0 from the reset, and its TriNode is not
    // touched again).
    occupied_.resize(num_nodes);
    uint32_t* occupied = occupied_.data();
    uint32_t num_occupied = 0;
    for (int k = 0; k < num_nodes; ++k) {
        occupied[num_occupied] = static_cast<uint32_t>(k);
        num_occupied += start[k + 1] != start[k] ? 1 : 0;
    }
    occupied_.resize(num_occupied);
    for (uint32_t j = 0; j < num_occupied; ++j) {
        const uint32_t k = occupied[j];
        model.nodes[k].begin = start[k];
        model.nodes[k].count = start[k + 1] - start[k];
    }
    // Pass 2: every dropped point goes to the one spare slot after the embedded ones. The
    // scatter writes each node's slots a run at a time, one ring after the other: the line a
    // node's next run starts is often not in the cache, and a store that misses holds up the
    // stores behind it. Each point therefore asks for the line after its own in the four
    // arrays (a prefetch for writing, which waits for nothing): by the node's next run it is
    // there. (At most `kAhead` slots ahead, clamped to the spare slot.)
    sx_.resize(total + 1), sy_.resize(total + 1), sz_.resize(total + 1), order_.resize(total + 1);
    float* sx = sx_.data();
    float* sy = sy_.data();
    float* sz = sz_.data();
    uint32_t* order = order_.data();
    constexpr uint32_t kAhead = 64 / sizeof(float);  // one cache line
    for (std::size_t i = 0; i < n; ++i) {
        const uint32_t node = point_node[i];
        const uint32_t slot = start[node] + (node != outside ? rank[i] : 0);
        const uint32_t ahead = std::min(slot + kAhead, total);
        __builtin_prefetch(sx + ahead, 1), __builtin_prefetch(sy + ahead, 1);
        __builtin_prefetch(sz + ahead, 1), __builtin_prefetch(order + ahead, 1);
        sx[slot] = px[i], sy[slot] = py[i], sz[slot] = pz[i];
        order[slot] = static_cast<uint32_t>(i);
    }
    sx_.resize(total), sy_.resize(total), sz_.resize(total), order_.resize(total);
}

}  // namespace travel
