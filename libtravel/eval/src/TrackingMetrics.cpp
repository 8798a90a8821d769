// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/eval/TrackingMetrics.hpp"

namespace travel::eval {

std::map<uint32_t, int> objectClusters(const std::vector<uint32_t>& instance,
                                       const std::vector<uint32_t>& cluster_id,
                                       std::size_t num_clusters, std::size_t min_points) {
    // object -> (points, points per cluster id); ordered maps: deterministic ties.
    std::map<uint32_t, std::size_t> points;
    std::map<uint32_t, std::map<uint32_t, std::size_t>> votes;
    for (std::size_t i = 0; i < instance.size(); ++i) {
        if (!instance[i]) continue;
        ++points[instance[i]];
        if (cluster_id[i] && cluster_id[i] <= num_clusters) ++votes[instance[i]][cluster_id[i]];
    }
    std::map<uint32_t, int> out;
    for (const auto& [object, n] : points) {
        if (n < min_points) continue;
        int best = -1;
        std::size_t most = 0;
        for (const auto& [id, count] : votes[object])
            if (count > most) most = count, best = int(id) - 1;
        out[object] = best;
    }
    return out;
}

double MotCounts::mota() const {
    if (!object_frames) return 0.0;
    return 1.0 - double(misses + false_positives + id_switches) / double(object_frames);
}

void MotAccumulator::add(const std::map<uint32_t, int>& matches,
                         const std::vector<ClusterSummary>& clusters) {
    std::vector<uint8_t> matched(clusters.size(), 0);
    for (const auto& [object, cluster] : matches) {
        ++counts_.object_frames;
        const uint32_t id = cluster >= 0 ? clusters[cluster].track_id : 0;
        if (cluster >= 0) matched[cluster] = 1;
        bool& tracked = was_tracked_[object];
        if (!id) {
            ++counts_.misses;
            tracked = false;
            continue;
        }
        counts_.track_ids[object].insert(id);
        const auto last = last_id_.find(object);
        if (last != last_id_.end()) {
            if (last->second != id) ++counts_.id_switches;
            if (!tracked) ++counts_.fragmentations;
        }
        last_id_[object] = id;
        tracked = true;
    }
    for (std::size_t c = 0; c < clusters.size(); ++c)
        if (!matched[c] && clusters[c].track_id && clusters[c].num_points >= min_points_)
            ++counts_.false_positives;
}

IdPersistence idPersistence(const std::vector<TrackedFrame>& frames, uint32_t min_points,
                            double max_distance) {
    IdPersistence out;
    for (std::size_t k = 0; k + 1 < frames.size(); ++k) {
        const TrackedFrame& a = frames[k];
        const TrackedFrame& b = frames[k + 1];
        for (const ClusterSummary& c : a.clusters) {
            if (c.num_points < min_points) continue;
            const Eigen::Vector3d p = a.world_T_aligned * c.centroid.cast<double>();
            double best = max_distance * max_distance;
            const ClusterSummary* next = nullptr;
            for (const ClusterSummary& d : b.clusters) {
                const double d2 = (b.world_T_aligned * d.centroid.cast<double>() - p).squaredNorm();
                if (d2 < best || (!next && d2 <= best)) best = d2, next = &d;  // ties: lower id
            }
            if (!next) continue;
            ++out.counted;
            if (c.track_id) ++out.counted_with_id;
            if (c.track_id && c.track_id == next->track_id) ++out.kept;
        }
    }
    return out;
}

}  // namespace travel::eval
