// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Breadth-first traversable graph search (B-TGS, paper Sec. III-C, eq. 2).
#pragma once

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

  private:
    void searchFrom(int root, int16_t component, const TriGridField& field, const Params& params,
                    TerrainModel& model);
    int nearestReached(const TriNode& cand, const TriGridField& field, const TerrainModel& model,
                       float max_dist2) const;
    std::vector<int> queue_;
    std::vector<int> candidates_;
};

}  // namespace travel
