// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// RANSAC ground plane (Fischler and Bolles, 1981), as commonly used for LiDAR ground removal:
// one plane for the whole scan, hypotheses from three random candidate points near the
// expected ground (z < -sensor_height + candidate_max_height), scored by their inlier count,
// the best refitted by least squares on its inliers. A fixed seed and iteration count make it
// deterministic and its cost constant.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "travel/Params.hpp"
#include "travel/PointCloud.hpp"
#include "travel/Preprocessing.hpp"

namespace travel::eval {

struct RansacOptions {
    int iterations = 100;               ///< hypotheses per frame
    double inlier_dist = 0.2;           ///< |distance| of a hypothesis' inliers; ground below it
    double candidate_max_height = 1.0;  ///< candidates: z < -sensor_height + this [m]
    double max_tilt_deg = 30.0;         ///< hypotheses whose normal is tilted more are rejected
    double outlier_dist = 0.5;          ///< more than this below the plane: Outlier [m]
    uint32_t seed = 42;                 ///< std::mt19937 seed, reset every frame
};

class RansacGround {
  public:
    explicit RansacGround(const RansacOptions& options = {});

    /// labels[i] for every point of `cloud`: Invalid, Ground (-outlier_dist <= signed
    /// distance < inlier_dist), Outlier (below that) or NonGround. Without a plane (fewer than
    /// 3 candidates, or no acceptable hypothesis) every valid point is NonGround.
    void segment(const AlignedCloud& cloud, const Params& params, std::vector<PointClass>& labels);

    const RansacOptions& options() const { return options_; }
    /// Plane of the last frame (n.p + d, n z-up); zero when none was found.
    const Eigen::Vector4f& plane() const { return plane_; }

  private:
    RansacOptions options_;
    std::vector<uint32_t> candidates_;
    std::vector<uint32_t> inliers_;
    Eigen::Vector4f plane_ = Eigen::Vector4f::Zero();
};

}  // namespace travel::eval
