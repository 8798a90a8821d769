// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Which cluster continues which track: the gates (centroid distance, box overlap, size ratio)
// and a deterministic greedy global nearest neighbour over the pairs that pass them. Everything
// is in the fixed world frame.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace travel {

/// An object's footprint in the world frame: where it is and how large.
struct WorldBox {
    Eigen::Vector2d centre{0, 0};                ///< centroid (xy) [m]
    Eigen::Vector3d min{0, 0, 0}, max{0, 0, 0};  ///< axis-aligned box [m]
    double size = 0;  ///< diagonal of the oriented box [m]: orientation-free size measure
};

struct AssociationGates {
    double max_distance = 2.0;    ///< centroid xy distance [m]
    double box_margin = 0.5;      ///< boxes must overlap once grown by this [m]
    double min_size_ratio = 0.4;  ///< smaller / larger size
};

/// The xy distance between the centres when the pair passes every gate, else a negative value.
double gatedDistance(const WorldBox& track, const WorldBox& cluster, const AssociationGates& gates);

/// One track-cluster pair that passes the gates.
struct AssociationPair {
    double distance;
    uint32_t track, cluster;
};

/// Greedy global nearest neighbour: the pairs passing the gates are taken in increasing
/// distance (ties: lower track index, then lower cluster index), each track and cluster at most
/// once. Fills track_to_cluster / cluster_to_track (-1: unmatched). `pairs` is scratch space
/// kept by the caller so that nothing is allocated once it has grown. Same input, same output.
void associateNearest(const std::vector<WorldBox>& tracks, const std::vector<WorldBox>& clusters,
                      const AssociationGates& gates, std::vector<AssociationPair>& pairs,
                      std::vector<int>& track_to_cluster, std::vector<int>& cluster_to_track);

}  // namespace travel
