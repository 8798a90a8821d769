// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Tri-grid field (TGF, paper Sec. III-B): a square grid of cells of side r centred on the sensor,
// each cell cut by its two diagonals into 4 triangular nodes. Points are bucketed into nodes by
// a counting sort, so each node's points are one contiguous slice of `order` (no per-node
// allocation, buffers reused across frames).
#pragma once

#include <array>
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

    /// Sizes (and maps) the per-point buffers for frames of up to `points` points.
    void reserve(std::size_t points);

    /// Bucket the valid points into nodes; fills model.nodes[*].begin/count and the sorted
    /// coordinates below. Invalid points and points outside the grid are left out (the caller
    /// labels them). Takes the points' nodes from cloud.node when preprocess() found them on
    /// this grid (preprocess(..., &geometry())), else finds them.
    void embed(const AlignedCloud& cloud, TerrainModel& model);

    const TriGridGeometry& geometry() const { return geometry_; }
    int cellsPerSide() const { return geometry_.cells_per_side; }
    int numNodes() const { return geometry_.numNodes(); }
    float resolution() const { return geometry_.resolution; }
    float originXY() const { return geometry_.origin_xy; }

    /// Node index of a point, or -1 outside the grid (TriGridGeometry::nodeAt).
    int nodeOf(float x, float y) const { return geometry_.nodeAt(x, y); }

    const Neighbours& neighbours(int node) const {
        return neighbours_[static_cast<std::size_t>(node)];
    }

    /// Corner k (0..2) of a node's triangle as a vertex id on the (2n+1) x (2n+1) lattice of
    /// half-cell steps (cell corners at even coordinates, cell centres at odd ones).
    int vertexId(int node, int k) const {
        return vertices_[static_cast<std::size_t>(3 * node + k)];
    }
    int numVertices() const {
        return (2 * geometry_.cells_per_side + 1) * (2 * geometry_.cells_per_side + 1);
    }
    /// xy of a lattice vertex.
    void vertexXY(int vertex, float& x, float& y) const;

    /// Sorted-by-node copies of the valid points (SoA) and the input index of each.
    const std::vector<float>& sx() const { return sx_; }
    const std::vector<float>& sy() const { return sy_; }
    const std::vector<float>& sz() const { return sz_; }
    const std::vector<uint32_t>& order() const { return order_; }
    /// The nodes that embed() gave points (count > 0), ascending.
    const std::vector<uint32_t>& occupiedNodes() const { return occupied_; }

  private:
    TriGridGeometry geometry_;
    std::vector<Neighbours> neighbours_;
    std::vector<int32_t> vertices_;  // 3 per node

    std::vector<uint32_t> point_node_;  // per input point, when the cloud has no nodes
    std::vector<uint32_t> rank_;        // per input point: earlier points of its node
    std::vector<uint32_t> node_start_;
    std::vector<float> sx_, sy_, sz_;
    std::vector<uint32_t> order_;
    std::vector<uint32_t> occupied_;
};

}  // namespace travel
