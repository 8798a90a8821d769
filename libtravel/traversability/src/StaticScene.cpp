// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/traversability/StaticScene.hpp"

#include <algorithm>

namespace travel {

const Result& withoutMovingClusters(const Result& result, Result& scratch) {
    const auto moving = [](const ClusterSummary& c) { return c.moving; };
    if (std::none_of(result.clusters.begin(), result.clusters.end(), moving)) return result;
    scratch = result;
    const std::size_t n = std::min(scratch.labels.size(), scratch.cluster_id.size());
    const std::size_t num_clusters = scratch.clusters.size();
    for (std::size_t i = 0; i < n; ++i) {
        const uint32_t id = scratch.cluster_id[i];
        if (id == 0 || id > num_clusters || !scratch.clusters[id - 1].moving ||
            scratch.labels[i] != PointClass::NonGround)
            continue;
        scratch.labels[i] = PointClass::Outlier;
        --scratch.class_counts[static_cast<int>(PointClass::NonGround)];
        ++scratch.class_counts[static_cast<int>(PointClass::Outlier)];
    }
    return scratch;
}

}  // namespace travel
