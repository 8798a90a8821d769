// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Per-point labels (paper eq. 5) from the refitted planes of the terrain model, and (with
// label_with_node_plane) the own planes of clear reached nodes and their neighbours: verges.
#pragma once

#include <array>
#include <vector>

#include "travel/Params.hpp"
#include "travel/Preprocessing.hpp"
#include "travel/TerrainModel.hpp"
#include "travel/TriGridField.hpp"

namespace travel {

/// Eq. 5 for one point: signed distance e to the ground plane -> Outlier below -outlier_dist,
/// Ground below ground_dist, NonGround otherwise. Shared with the baselines (GPF, RANSAC).
inline PointClass classifyByPlaneDistance(float e, float ground_dist, float outlier_dist) {
    return e < -outlier_dist ? PointClass::Outlier
           : e < ground_dist ? PointClass::Ground
                             : PointClass::NonGround;
}

/// labels.size() == cloud size afterwards; every point gets exactly one class. `model` is the
/// one field.embed() filled last (its nodes with points are field.occupiedNodes()).
/// Returns the number of points per class (indexed by PointClass value). With `heights`, each
/// point of a node with a ground plane gets the signed distance e that labelled it (+inf for
/// the others): the face rule's foot height (VerticalFaces).
std::array<std::size_t, 4> labelPoints(const TriGridField& field, const AlignedCloud& cloud,
                                       const Params& params, const TerrainModel& model,
                                       std::vector<PointClass>& labels,
                                       std::vector<float>* heights = nullptr);

}  // namespace travel
