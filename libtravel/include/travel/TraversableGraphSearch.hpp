// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Breadth-first traversable graph search (B-TGS, paper Sec. III-C, eq. 2).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "travel/Params.hpp"
#include "travel/TerrainModel.hpp"
#include "travel/TriGridField.hpp"

namespace travel {

/// Local convexity/concavity test of the edge between two terrain nodes (eq. 2). Symmetric.
bool isTraversableEdge(const TriNode& a, const TriNode& b, const Params& params);

class TraversableGraphSearch {
  public:
    /// Sets reached / component of every node and model.seed_node / num_components.
    void run(const TriGridField& field, const Params& params, TerrainModel& model);
    /// Sizes (and maps) the per-node buffers for the field, so the first frame pays no page
    /// faults for them.
    void reserve(const TriGridField& field);

  private:
    // What the searches read of a terrain node, copied once per frame into a compact array
    // (a TriNode is 112 bytes, most of them other stages' fields).
    struct HotNode {
        Eigen::Vector3f mean, normal;
        float d, weight;
    };
    void searchFrom(int root, int16_t component, const TriGridField& field, const Params& params,
                    TerrainModel& model);
    // The nearest reached node of a re-seeding candidate, as last computed: `seen` = how many
    // nodes of reached_ it accounts for (0: none yet); cx, cy = the candidate's cell (-1:
    // outside the grid).
    struct Nearest {
        int node = -1;
        float d2 = 0.f;
        std::size_t seen = 0;
        int cx = -1, cy = -1;
    };
    void nearestReached(const Eigen::Vector2f& xy, const TriGridField& field, float max_dist2,
                        Nearest& near) const;
    int nearestReachedNow(std::size_t c, const TriGridField& field, float max_dist2);
    void markReached(int node, int16_t component, const TriGridField& field, TerrainModel& model);
    // Where a reached node is: its mean (xy) and its cell.
    struct ReachedWhere {
        Eigen::Vector2f xy;
        int cx, cy;
    };
    std::vector<int> reached_;  // every reached node, in the order the searches reached them
    std::vector<ReachedWhere> reached_where_;  // the same nodes' positions
    std::vector<uint8_t> node_reached_;        // per node: model.nodes[id].reached
    std::vector<Eigen::Vector2f> node_xy_;     // per node: its mean's xy (set when reached)
    std::vector<int32_t> terrain_slot_;        // per node: its index in hot_, -1 if not terrain
    std::vector<HotNode> hot_;                 // the terrain nodes, in increasing node id
    std::vector<int32_t> terrain_;             // their node ids
    // Cells holding a reached node, as bits: row iy's cells ix at row_cells_[iy * words_ +
    // ix / 64], column ix's cells iy at col_cells_[ix * words_ + iy / 64]. The ring scans
    // visit only these cells, not the window's empty ones.
    std::vector<uint64_t> row_cells_, col_cells_;
    int words_ = 0;
    std::vector<int> candidates_;
    std::vector<uint64_t> candidate_keys_;  // (weight, id) sort keys of the candidates
    std::vector<Nearest> nearest_;          // per candidate
    int window_rings_ = 0;                  // Chebyshev radius [cells] of the nearest-node window
};

}  // namespace travel
