// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Tri-grid field (TGF, paper Sec. III-B): a square grid of cells of side r centred on the sensor,
// each cell cut by its two diagonals into 4 triangular nodes. Points are bucketed into nodes by
// a counting sort, so each node's points are one contiguous slice of `order` (no per-node
// allocation, buffers reused across frames).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "travel/Params.hpp"
#include "travel/Preprocessing.hpp"
#include "travel/TerrainModel.hpp"

namespace travel {

class TriGridField {
  public:
    /// Up to 14 neighbours per node: the 3 other triangles of its cell and every triangle of
    /// the 8 surrounding cells that shares a vertex with it. Built geometrically (by shared
    /// vertices), so no hand-written table can have a typo.
    static constexpr int kMaxNeighbours = 14;
    struct Neighbours {
        std::array<int32_t, kMaxNeighbours> ids;
        int count = 0;
    };

    /// (Re)size the grid for the parameters: R = max_range, rounded up to whole cells.
    void configure(const Params& params);

    /// Bucket the valid points into nodes; fills model.nodes[*].begin/count and the sorted
    /// coordinates below. Invalid points and points outside the grid are left out (the caller
    /// labels them).
    void embed(const AlignedCloud& cloud, TerrainModel& model);

    int cellsPerSide() const { return cells_per_side_; }
    int numNodes() const { return 4 * cells_per_side_ * cells_per_side_; }
    float resolution() const { return resolution_; }
    float originXY() const { return origin_; }

    /// Node index of a point, or -1 outside the grid.
    int nodeOf(float x, float y) const;

    const Neighbours& neighbours(int node) const { return neighbours_[node]; }

    /// Corner k (0..2) of a node's triangle as a vertex id on the (2n+1) x (2n+1) lattice of
    /// half-cell steps (cell corners at even coordinates, cell centres at odd ones).
    int vertexId(int node, int k) const { return vertices_[3 * node + k]; }
    int numVertices() const { return (2 * cells_per_side_ + 1) * (2 * cells_per_side_ + 1); }
    /// xy of a lattice vertex.
    void vertexXY(int vertex, float& x, float& y) const;

    /// Sorted-by-node copies of the valid points (SoA) and the input index of each.
    const std::vector<float>& sx() const { return sx_; }
    const std::vector<float>& sy() const { return sy_; }
    const std::vector<float>& sz() const { return sz_; }
    const std::vector<uint32_t>& order() const { return order_; }

  private:
    float resolution_ = 0.f;
    float origin_ = 0.f;  // x and y of the grid's lower-left corner
    int cells_per_side_ = 0;
    std::vector<Neighbours> neighbours_;
    std::vector<int32_t> vertices_;  // 3 per node

    std::vector<int32_t> point_node_;  // per input point, -1 = not embedded
    std::vector<uint32_t> node_start_;
    std::vector<float> sx_, sy_, sz_;
    std::vector<uint32_t> order_;
};

inline int TriGridField::nodeOf(float x, float y) const {
    const float inv_r = 1.f / resolution_;
    const float gx = (x - origin_) * inv_r, gy = (y - origin_) * inv_r;
    // Bounds before the float->int conversion (huge values would be undefined); NaN fails too.
    const float limit = static_cast<float>(cells_per_side_);
    if (!(gx >= 0.f && gy >= 0.f && gx < limit && gy < limit)) return -1;
    const int ix = static_cast<int>(gx), iy = static_cast<int>(gy);
    // Which of the 4 triangles: compare the offsets from the cell centre (diagonals |u| = |v|).
    const float u = gx - (static_cast<float>(ix) + 0.5f);
    const float v = gy - (static_cast<float>(iy) + 0.5f);
    // Branch-free (the choice is unpredictable along a scan line): east 0, north 1, west 2,
    // south 3.
    const int horizontal = std::fabs(u) >= std::fabs(v);
    const int negative = (horizontal & (u < 0.f)) | ((horizontal ^ 1) & (v < 0.f));
    const int tri = (horizontal ^ 1) + 2 * negative;
    return 4 * (iy * cells_per_side_ + ix) + tri;
}

}  // namespace travel
