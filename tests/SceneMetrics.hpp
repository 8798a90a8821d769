// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Scores of a segmentation against the synthetic LiDAR's exact ground truth (tests only).
#pragma once

#include <cmath>
#include <cstddef>
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

/// No-return points are not scored; with a cloud and max_range, neither are points farther than
/// max_range from the sensor (to compare scans whose far coverage differs).
inline SceneScores scoreScene(const sim::GroundTruth& gt, const std::vector<PointClass>& labels,
                              const PointCloud* cloud = nullptr, float max_range = 0.f) {
    SceneScores s;
    for (std::size_t i = 0; i < gt.size(); ++i) {
        if (gt.cls[i] == sim::NoReturn) continue;
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

}  // namespace travel::test
