// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Which cluster continues which track: the gates (centroid distance, box overlap, size ratio)
// and a deterministic greedy global nearest neighbour over the pairs that pass them. Everything
// is in the fixed world frame.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "travel/tracking/ObjectExtent.hpp"

namespace travel {

/// An object's footprint in the world frame: where it is and how large.
struct WorldBox {
    Eigen::Vector2d centre{0, 0};                ///< centroid (xy) [m]
    Eigen::Vector3d min{0, 0, 0}, max{0, 0, 0};  ///< axis-aligned box [m]
    double size = 0;  ///< diagonal of the oriented box [m]: orientation-free size measure
    FlatBox flat;     ///< the oriented box in the xy plane
};

struct AssociationGates {
    double max_distance = 2.0;    ///< centroid xy distance [m]
    double box_margin = 0.5;      ///< boxes must overlap once grown by this [m]
    double min_size_ratio = 0.4;  ///< smaller / larger size
};

/// The xy distance from the track's predicted position (track.centre) to `measured`, the
/// cluster's position as this track locates it, when the pair passes every gate, else a
/// negative value.
double gatedDistance(const WorldBox& track, const WorldBox& cluster,
                     const Eigen::Vector2d& measured, const AssociationGates& gates);

/// One track-cluster pair that passes the gates.
struct AssociationPair {
    double distance;
    uint32_t track, cluster;
};

/// Greedy global nearest neighbour over `pairs` (those that pass the gates): taken in increasing
/// distance (ties: lower track index, then lower cluster index), each track and cluster at most
/// once. Fills track_to_cluster / cluster_to_track (-1: unmatched). Same input, same output.
void assignNearest(std::vector<AssociationPair>& pairs, std::size_t num_tracks,
                   std::size_t num_clusters, std::vector<int>& track_to_cluster,
                   std::vector<int>& cluster_to_track);

/// assignNearest() over every pair whose distance(track, cluster) is >= 0. `pairs` is scratch
/// space kept by the caller so that nothing is allocated once it has grown.
template <class Distance>
void associateNearest(std::size_t num_tracks, std::size_t num_clusters, Distance&& distance,
                      std::vector<AssociationPair>& pairs, std::vector<int>& track_to_cluster,
                      std::vector<int>& cluster_to_track) {
    pairs.clear();
    for (uint32_t t = 0; t < num_tracks; ++t)
        for (uint32_t c = 0; c < num_clusters; ++c) {
            const double d = distance(t, c);
            if (d >= 0) pairs.push_back({d, t, c});
        }
    assignNearest(pairs, num_tracks, num_clusters, track_to_cluster, cluster_to_track);
}

}  // namespace travel
