// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/tracking/TrackAssociation.hpp"

#include <algorithm>

namespace travel {

double gatedDistance(const WorldBox& track, const WorldBox& cluster,
                     const Eigen::Vector2d& measured, const AssociationGates& gates) {
    const double distance = (track.centre - measured).norm();
    if (!(distance <= gates.max_distance)) return -1;
    const double m = gates.box_margin;
    for (int a = 0; a < 3; ++a)
        if (track.min[a] - m > cluster.max[a] || cluster.min[a] - m > track.max[a]) return -1;
    const double small = std::min(track.size, cluster.size);
    const double large = std::max(track.size, cluster.size);
    if (large > 0 && small < gates.min_size_ratio * large) return -1;
    return distance;
}

void assignNearest(std::vector<AssociationPair>& pairs, std::size_t num_tracks,
                   std::size_t num_clusters, std::vector<int>& track_to_cluster,
                   std::vector<int>& cluster_to_track) {
    std::sort(pairs.begin(), pairs.end(), [](const AssociationPair& a, const AssociationPair& b) {
        if (a.distance != b.distance) return a.distance < b.distance;
        if (a.track != b.track) return a.track < b.track;
        return a.cluster < b.cluster;
    });
    track_to_cluster.assign(num_tracks, -1);
    cluster_to_track.assign(num_clusters, -1);
    for (const AssociationPair& p : pairs) {
        if (track_to_cluster[p.track] >= 0 || cluster_to_track[p.cluster] >= 0) continue;
        track_to_cluster[p.track] = static_cast<int>(p.cluster);
        cluster_to_track[p.cluster] = static_cast<int>(p.track);
    }
}

}  // namespace travel
