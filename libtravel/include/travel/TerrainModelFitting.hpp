// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Traversable terrain model fitting (TTMF, paper Sec. III-D): traversable nodes vote heights at
// their triangle corners; every node whose three corners received votes gets the plane through
// them, which recovers the ground under and around objects.
#pragma once

#include <vector>

#include "travel/Params.hpp"
#include "travel/TerrainModel.hpp"
#include "travel/TriGridField.hpp"

namespace travel {

class TerrainModelFitting {
  public:
    /// Sets corner_z, refit_* and traversable of every node. With params.ttmf == false,
    /// traversable = reached and the refit plane is the node's own plane (ablation). `model` is
    /// the one field.embed() filled last: the votes are looked for among field.occupiedNodes().
    void run(const TriGridField& field, const Params& params, TerrainModel& model);
    /// Sizes (and maps) the per-vertex buffers for the field (no page faults on the first frame).
    void reserve(const TriGridField& field);

  private:
    std::vector<double> vote_weight_, vote_weighted_z_;
};

}  // namespace travel
