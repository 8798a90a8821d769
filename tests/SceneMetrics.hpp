// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Scores of a segmentation against the synthetic LiDAR's exact ground truth (tests only).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <vector>

#include "travel/PointCloud.hpp"
#include "travel/sim/SyntheticLidar.hpp"

namespace travel::test {

struct SceneScores {
    std::size_t tp = 0, fp = 0, fn = 0, tn = 0;
    /// Non-ground points standing more than 0.3 m above the true ground but labelled ground.
    std::size_t high_obstacle_as_ground = 0;
    double precision() const { return tp + fp ? double(tp) / double(tp + fp) : 1.0; }
    double recall() const { return tp + fn ? double(tp) / double(tp + fn) : 1.0; }
    double f1() const {
        const double p = precision(), r = recall();
        return p + r > 0 ? 2 * p * r / (p + r) : 0.0;
    }
};

/// No-return points and returns mirrored by water (sim::Reflection, SemanticKITTI's outliers)
/// are not scored; with a cloud and max_range, neither are points farther than
/// max_range from the sensor (to compare scans whose far coverage differs).
inline SceneScores scoreScene(const sim::GroundTruth& gt, const std::vector<PointClass>& labels,
                              const PointCloud* cloud = nullptr, float max_range = 0.f) {
    SceneScores s;
    for (std::size_t i = 0; i < gt.size(); ++i) {
        if (gt.cls[i] == sim::NoReturn || gt.cls[i] == sim::Reflection) continue;
        if (cloud && std::hypot(cloud->x[i], cloud->y[i], cloud->z[i]) > max_range) continue;
        const bool truth = gt.cls[i] == sim::Ground;
        const bool pred = labels[i] == PointClass::Ground;
        if (truth && pred) ++s.tp;
        if (!truth && pred) ++s.fp;
        if (truth && !pred) ++s.fn;
        if (!truth && !pred) ++s.tn;
        if (!truth && pred && gt.height_above_ground[i] > 0.3f) ++s.high_obstacle_as_ground;
    }
    return s;
}

/// One ground-truth object: coverage = largest share of its non-ground-labelled points (the
/// clustering's input) inside one cluster; purity = share of that cluster belonging to it.
struct ObjectScore {
    std::size_t points = 0;
    uint32_t best_cluster = 0;
    double coverage = 0, purity = 0;
};

inline ObjectScore scoreObject(const sim::GroundTruth& gt, const std::vector<PointClass>& labels,
                               const std::vector<uint32_t>& cluster_id, uint32_t instance) {
    ObjectScore s;
    std::map<uint32_t, std::size_t> per_cluster;
    for (std::size_t i = 0; i < gt.size(); ++i) {
        if (gt.instance[i] != instance || labels[i] != PointClass::NonGround) continue;
        ++s.points;
        if (cluster_id[i]) ++per_cluster[cluster_id[i]];
    }
    std::size_t best = 0;
    for (const auto& [id, count] : per_cluster)
        if (count > best) best = count, s.best_cluster = id;
    if (s.points == 0 || s.best_cluster == 0) return s;
    s.coverage = double(best) / double(s.points);
    std::size_t cluster_size = 0;
    for (const uint32_t id : cluster_id) cluster_size += id == s.best_cluster;
    s.purity = double(best) / double(cluster_size);
    return s;
}

}  // namespace travel::test
