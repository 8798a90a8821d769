// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/eval/RansacGround.hpp"

#include "travel/GroundLabelling.hpp"

#include <cmath>
#include <random>

#include "travel/eval/GroundPlaneFitting.hpp"

namespace travel::eval {

constexpr double kPi = 3.14159265358979323846;

RansacGround::RansacGround(const RansacOptions& options) : options_(options) {}

void RansacGround::segment(const AlignedCloud& cloud, const Params& params,
                           std::vector<PointClass>& labels) {
    const std::size_t n = cloud.x.size();
    labels.assign(n, PointClass::Invalid);
    candidates_.clear();
    const float candidate_max_z =
        static_cast<float>(-params.sensor_height + options_.candidate_max_height);
    for (std::size_t i = 0; i < n; ++i) {
        if (!cloud.valid[i]) continue;
        labels[i] = PointClass::NonGround;
        if (cloud.z[i] < candidate_max_z) candidates_.push_back(static_cast<uint32_t>(i));
    }
    plane_.setZero();
    if (candidates_.size() < 3) return;

    // Reseeded every frame: the same frame gives the same plane whatever came before.
    std::mt19937 rng(options_.seed);
    std::uniform_int_distribution<std::size_t> pick(0, candidates_.size() - 1);
    const float min_normal_z = static_cast<float>(std::cos(options_.max_tilt_deg * kPi / 180.0));
    const float inlier = static_cast<float>(options_.inlier_dist);
    std::size_t best_count = 0;
    Eigen::Vector4f best = Eigen::Vector4f::Zero();
    for (int it = 0; it < options_.iterations; ++it) {
        const uint32_t a = candidates_[pick(rng)], b = candidates_[pick(rng)],
                       c = candidates_[pick(rng)];
        // Plane through the three samples: normal = (b - a) x (c - a).
        const float ux = cloud.x[b] - cloud.x[a], uy = cloud.y[b] - cloud.y[a],
                    uz = cloud.z[b] - cloud.z[a];
        const float vx = cloud.x[c] - cloud.x[a], vy = cloud.y[c] - cloud.y[a],
                    vz = cloud.z[c] - cloud.z[a];
        float nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
        const float norm = std::sqrt(nx * nx + ny * ny + nz * nz);
        if (!(norm > 1e-6f)) continue;           // collinear or repeated samples
        const float sign = nz < 0 ? -1.f : 1.f;  // z-up
        nx *= sign / norm, ny *= sign / norm, nz *= sign / norm;
        if (nz < min_normal_z) continue;  // a wall, not the ground
        const float d = -(nx * cloud.x[a] + ny * cloud.y[a] + nz * cloud.z[a]);
        std::size_t count = 0;
        for (const uint32_t i : candidates_)
            count += std::abs(nx * cloud.x[i] + ny * cloud.y[i] + nz * cloud.z[i] + d) < inlier;
        if (count > best_count) best_count = count, best << nx, ny, nz, d;
    }
    if (best_count < 3) return;

    // Least-squares refit on the best hypothesis' inliers (three points are noisy).
    inliers_.clear();
    for (const uint32_t i : candidates_)
        if (std::abs(best[0] * cloud.x[i] + best[1] * cloud.y[i] + best[2] * cloud.z[i] + best[3]) <
            inlier)
            inliers_.push_back(i);
    Eigen::Vector4f refined;
    plane_ = fitPlanePca(cloud, inliers_, refined) && refined[2] >= min_normal_z ? refined : best;

    const float outlier = static_cast<float>(options_.outlier_dist);
    for (std::size_t i = 0; i < n; ++i) {
        if (!cloud.valid[i]) continue;
        const float d =
            plane_[0] * cloud.x[i] + plane_[1] * cloud.y[i] + plane_[2] * cloud.z[i] + plane_[3];
        labels[i] = classifyByPlaneDistance(d, inlier, outlier);
    }
}

}  // namespace travel::eval
