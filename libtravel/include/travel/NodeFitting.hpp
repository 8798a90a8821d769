// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Node-wise terrain model (paper Sec. III-B): per tri-grid node, an iterative PCA plane over
// the lowest points, the paper's weight (eq. 1) and the terrain / obstacle / unknown class.
#pragma once

#include "travel/Params.hpp"
#include "travel/TerrainModel.hpp"
#include "travel/TriGridField.hpp"

namespace travel {

/// Fills normal, mean, d, eigenvalues, weight, lpr and node_class of every node with points
/// (field.occupiedNodes(): `model` is the one field.embed() filled last).
void fitNodes(const TriGridField& field, const Params& params, TerrainModel& model);

}  // namespace travel
