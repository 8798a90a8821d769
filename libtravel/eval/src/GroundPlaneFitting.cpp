// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/eval/GroundPlaneFitting.hpp"

#include "travel/GroundLabelling.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace travel::eval {

bool fitPlanePca(const AlignedCloud& cloud, const std::vector<uint32_t>& indices,
                 Eigen::Vector4f& plane) {
    if (indices.size() < 3) return false;
    // Double sums: a frame's z spread is small against its x, y, and float cancels.
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    Eigen::Matrix3d sum_sq = Eigen::Matrix3d::Zero();
    for (const uint32_t i : indices) {
        const Eigen::Vector3d p(cloud.x[i], cloud.y[i], cloud.z[i]);
        sum += p;
        sum_sq.noalias() += p * p.transpose();
    }
    const double n = static_cast<double>(indices.size());
    const Eigen::Vector3d mean = sum / n;
    const Eigen::Matrix3d cov = sum_sq / n - mean * mean.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    Eigen::Vector3d normal = eig.eigenvectors().col(0);  // smallest eigenvalue first
    if (!normal.allFinite()) return false;
    if (normal.z() < 0) normal = -normal;
    plane << normal.cast<float>(), static_cast<float>(-normal.dot(mean));
    return true;
}

GroundPlaneFitting::GroundPlaneFitting(const GpfOptions& options) : options_(options) {}

void GroundPlaneFitting::segment(const AlignedCloud& cloud, const Params& params,
                                 std::vector<PointClass>& labels) {
    const std::size_t n = cloud.x.size();
    labels.assign(n, PointClass::Invalid);
    order_.clear();
    for (std::size_t i = 0; i < n; ++i)
        if (cloud.valid[i]) order_.push_back(static_cast<uint32_t>(i));

    // The paper does not fix the segment bounds; equal point counts along x (quantiles) adapt
    // to the density falling with range. nth_element keeps it O(n) and deterministic.
    const int segments = std::max(1, options_.num_segments);
    const auto by_x = [&](uint32_t a, uint32_t b) {
        return cloud.x[a] < cloud.x[b] || (cloud.x[a] == cloud.x[b] && a < b);
    };
    const std::size_t m = order_.size();
    for (int s = 1; s < segments; ++s)
        std::nth_element(order_.begin() + static_cast<std::ptrdiff_t>(m * (s - 1) / segments),
                         order_.begin() + static_cast<std::ptrdiff_t>(m * s / segments),
                         order_.end(), by_x);

    planes_.clear();
    const float th_dist = static_cast<float>(options_.dist_threshold);
    const float outlier = static_cast<float>(options_.outlier_dist);
    const float noise_floor =
        static_cast<float>(-options_.noise_floor_factor * params.sensor_height);
    for (int s = 0; s < segments; ++s) {
        const std::size_t begin = m * s / segments, end = m * (s + 1) / segments;
        if (begin == end) continue;
        // LPR: mean z of the N_LPR lowest points of the segment.
        lowest_z_.clear();
        for (std::size_t k = begin; k < end; ++k)
            if (cloud.z[order_[k]] >= noise_floor) lowest_z_.push_back(cloud.z[order_[k]]);
        if (lowest_z_.empty()) {
            for (std::size_t k = begin; k < end; ++k) labels[order_[k]] = PointClass::NonGround;
            planes_.push_back(Eigen::Vector4f::Zero());
            continue;
        }
        const std::size_t num_lpr =
            std::min(lowest_z_.size(), static_cast<std::size_t>(std::max(1, options_.num_lpr)));
        std::nth_element(lowest_z_.begin(), lowest_z_.begin() + (num_lpr - 1), lowest_z_.end());
        double lpr = 0;
        for (std::size_t k = 0; k < num_lpr; ++k) lpr += lowest_z_[k];
        lpr /= static_cast<double>(num_lpr);

        // Seeds: z < LPR + Th_seeds.
        selected_.clear();
        const float seed_max = static_cast<float>(lpr + options_.seed_threshold);
        for (std::size_t k = begin; k < end; ++k) {
            const float z = cloud.z[order_[k]];
            if (z < seed_max && z >= noise_floor) selected_.push_back(order_[k]);
        }

        // N_iter times: PCA plane of the selection, then reselect |distance| < Th_dist.
        Eigen::Vector4f plane = Eigen::Vector4f::Zero();
        bool have_plane = false;
        for (int it = 0; it < options_.num_iterations; ++it) {
            if (!fitPlanePca(cloud, selected_, plane)) break;
            have_plane = true;
            selected_.clear();
            for (std::size_t k = begin; k < end; ++k) {
                const uint32_t i = order_[k];
                const float d = plane[0] * cloud.x[i] + plane[1] * cloud.y[i] +
                                plane[2] * cloud.z[i] + plane[3];
                if (std::abs(d) < th_dist) selected_.push_back(i);
            }
        }
        planes_.push_back(plane);
        for (std::size_t k = begin; k < end; ++k) {
            const uint32_t i = order_[k];
            if (!have_plane) {
                labels[i] = PointClass::NonGround;
                continue;
            }
            const float d =
                plane[0] * cloud.x[i] + plane[1] * cloud.y[i] + plane[2] * cloud.z[i] + plane[3];
            labels[i] = classifyByPlaneDistance(d, th_dist, outlier);
        }
    }
}

}  // namespace travel::eval
