// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// How well tracks keep their identity (docs/tracking.md):
//  - with ground truth (synthetic sequences, travel::sim::TrafficSequence): CLEAR-MOT style
//    counts (Bernardin & Stiefelhagen 2008) at the level of clusters. A ground-truth object is
//    matched in a frame by the cluster holding most of its points (ties: the smaller cluster
//    id); the match is that cluster's track id (0: untracked, a miss). An ID switch is a matched
//    track id other than the object's previous non-zero one; a fragmentation is a return to
//    tracked after a miss. False positives: confirmed clusters of at least min_points points
//    that are no object's match.
//    MOTA = 1 - (misses + false positives + ID switches) / object-frames.
//  - without ground truth (real sequences): id persistence. A cluster of at least min_points
//    whose world centroid lies within max_distance of a cluster of the next frame (the nearest)
//    counts; it keeps its id when both carry the same non-zero track id.
#pragma once

#include <Eigen/Geometry>
#include <cstddef>
#include <cstdint>
#include <map>
#include <set>
#include <vector>

#include "travel/Clusters.hpp"

namespace travel::eval {

/// For each ground-truth object (instance id > 0) with at least min_points points: the index
/// (cluster id - 1) of the cluster holding most of its points, -1 when none holds any.
/// `instance` and `cluster_id` are per point.
std::map<uint32_t, int> objectClusters(const std::vector<uint32_t>& instance,
                                       const std::vector<uint32_t>& cluster_id,
                                       std::size_t num_clusters, std::size_t min_points);

struct MotCounts {
    std::size_t object_frames = 0;  ///< objects visible (>= min_points points), summed over frames
    std::size_t misses = 0, false_positives = 0, id_switches = 0, fragmentations = 0;
    std::map<uint32_t, std::set<uint32_t>> track_ids;  ///< per object: every track id it got
    double mota() const;
};

/// Accumulates MotCounts frame by frame (the previous ids live here).
class MotAccumulator {
  public:
    /// `matches`: objectClusters() of the frame (objects of at least `min_points` points);
    /// `clusters`: the frame's tracked clusters.
    explicit MotAccumulator(std::size_t min_points) : min_points_(min_points) {}
    void add(const std::map<uint32_t, int>& matches, const std::vector<ClusterSummary>& clusters);
    const MotCounts& counts() const { return counts_; }

  private:
    std::size_t min_points_;
    MotCounts counts_;
    std::map<uint32_t, uint32_t> last_id_;  ///< object -> last non-zero track id
    std::map<uint32_t, bool> was_tracked_;
};

struct TrackedFrame {
    std::vector<ClusterSummary> clusters;
    Eigen::Isometry3d world_T_aligned = Eigen::Isometry3d::Identity();
};

struct IdPersistence {
    std::size_t counted = 0;  ///< large clusters with a cluster within max_distance next frame
    std::size_t kept = 0;     ///< ... with the same non-zero track id
    std::size_t counted_with_id = 0;  ///< ... among those that had a track id
    double share() const { return counted ? double(kept) / double(counted) : 0.0; }
    double shareOfTracked() const {
        return counted_with_id ? double(kept) / double(counted_with_id) : 0.0;
    }
};

IdPersistence idPersistence(const std::vector<TrackedFrame>& frames, uint32_t min_points = 300,
                            double max_distance = 1.0);

}  // namespace travel::eval
