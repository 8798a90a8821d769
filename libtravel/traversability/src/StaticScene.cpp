// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/traversability/StaticScene.hpp"

#include <algorithm>
#include <cmath>

namespace travel {
namespace {

bool anyMoving(const Result& result) {
    return std::any_of(result.clusters.begin(), result.clusters.end(),
                       [](const ClusterSummary& c) { return c.moving; });
}

void relabelOutlier(Result& r, std::size_t i) {
    ++r.class_counts[static_cast<int>(PointClass::Outlier)];
    --r.class_counts[static_cast<int>(r.labels[i])];
    r.labels[i] = PointClass::Outlier;
}

/// Relabels the non-ground points of moving clusters in `r` (a copy of the result).
void relabelMovingClusters(Result& r) {
    const std::size_t n = std::min(r.labels.size(), r.cluster_id.size());
    const std::size_t num_clusters = r.clusters.size();
    for (std::size_t i = 0; i < n; ++i) {
        const uint32_t id = r.cluster_id[i];
        if (id == 0 || id > num_clusters || !r.clusters[id - 1].moving ||
            r.labels[i] != PointClass::NonGround)
            continue;
        relabelOutlier(r, i);
    }
}

}  // namespace

void MovingFootprints::build(const std::vector<ClusterSummary>& clusters) {
    boxes_.clear();
    for (const ClusterSummary& c : clusters)
        if (c.moving && c.obb_center.allFinite() && std::isfinite(c.obb_yaw))
            boxes_.push_back({c.obb_center.head<2>(), std::cos(c.obb_yaw), std::sin(c.obb_yaw),
                              0.5f * c.obb_extent.x() + kMargin,
                              0.5f * c.obb_extent.y() + kMargin});
}

bool MovingFootprints::contains(float x, float y) const {
    for (const Box& b : boxes_) {
        const float dx = x - b.centre.x(), dy = y - b.centre.y();
        if (std::abs(b.cos_yaw * dx + b.sin_yaw * dy) <= b.half_length &&
            std::abs(-b.sin_yaw * dx + b.cos_yaw * dy) <= b.half_width)
            return true;
    }
    return false;
}

const Result& withoutMovingClusters(const Result& result, Result& scratch) {
    if (!anyMoving(result)) return result;
    scratch = result;
    relabelMovingClusters(scratch);
    return scratch;
}

const Result& withoutMovingObjects(const Result& result, const AlignedCloud& aligned,
                                   Result& scratch) {
    if (!anyMoving(result)) return result;
    scratch = result;
    relabelMovingClusters(scratch);
    MovingFootprints footprints;  // a few boxes: only when something moves
    footprints.build(scratch.clusters);
    const std::size_t n = std::min({scratch.labels.size(), aligned.x.size(), aligned.y.size()});
    for (std::size_t i = 0; i < n; ++i) {
        const PointClass label = scratch.labels[i];
        if ((label == PointClass::Ground || label == PointClass::NonGround) &&
            footprints.contains(aligned.x[i], aligned.y[i]))
            relabelOutlier(scratch, i);
    }
    return scratch;
}

}  // namespace travel
