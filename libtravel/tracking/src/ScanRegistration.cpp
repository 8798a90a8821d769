// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/tracking/ScanRegistration.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace travel {
namespace {

// 21 bits per axis: +-1e6 cells.
int64_t packKey(int64_t ix, int64_t iy, int64_t iz) {
    constexpr int64_t kOffset = 1 << 20, kMask = (1 << 21) - 1;
    return (((ix + kOffset) & kMask) << 42) | (((iy + kOffset) & kMask) << 21) |
           ((iz + kOffset) & kMask);
}

int64_t voxelKey(const Eigen::Vector3d& p, double voxel) {
    return packKey(int64_t(std::floor(p.x() / voxel)), int64_t(std::floor(p.y() / voxel)),
                   int64_t(std::floor(p.z() / voxel)));
}

}  // namespace

std::vector<Eigen::Vector3d> voxelFilter(const std::vector<Eigen::Vector3d>& points, double voxel) {
    std::vector<std::pair<int64_t, uint32_t>> keyed(points.size());
    for (uint32_t i = 0; i < points.size(); ++i) keyed[i] = {voxelKey(points[i], voxel), i};
    std::sort(keyed.begin(), keyed.end());
    std::vector<Eigen::Vector3d> out;
    for (std::size_t a = 0; a < keyed.size();) {
        std::size_t b = a;
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        for (; b < keyed.size() && keyed[b].first == keyed[a].first; ++b)
            sum += points[keyed[b].second];
        out.push_back(sum / double(b - a));
        a = b;
    }
    return out;
}

int64_t ScanRegistration::cellKey(int64_t ix, int64_t iy, int64_t iz) {
    return packKey(ix, iy, iz);
}

int64_t ScanRegistration::cellKey(const Eigen::Vector3d& p) const {
    const double s = params_.neighbour_radius;
    return packKey(int64_t(std::floor(p.x() / s)), int64_t(std::floor(p.y() / s)),
                   int64_t(std::floor(p.z() / s)));
}

void ScanRegistration::setTarget(const std::vector<Eigen::Vector3d>& points) {
    target_ = voxelFilter(points, params_.target_voxel);
    std::vector<std::pair<int64_t, uint32_t>> keyed(target_.size());
    for (uint32_t i = 0; i < target_.size(); ++i) keyed[i] = {cellKey(target_[i]), i};
    std::sort(keyed.begin(), keyed.end());
    order_.resize(keyed.size());
    cells_.clear();
    for (uint32_t a = 0; a < keyed.size();) {
        uint32_t b = a;
        for (; b < keyed.size() && keyed[b].first == keyed[a].first; ++b)
            order_[b] = keyed[b].second;
        cells_.emplace(keyed[a].first, std::make_pair(a, b));
        a = b;
    }
    // Normals are estimated when a correspondence first needs them (most target points are
    // never the nearest of a source point): see normalAt.
    normals_.assign(target_.size(), Eigen::Vector3d::Zero());
    has_normal_.assign(target_.size(), kNormalUnknown);
}

bool ScanRegistration::normalAt(uint32_t i) {
    if (has_normal_[i] != kNormalUnknown) return has_normal_[i] == kNormalFound;
    has_normal_[i] = kNormalNone;
    // PCA of the k nearest points, all within the radius.
    const int k = params_.normal_neighbours;
    const double r2 = params_.neighbour_radius * params_.neighbour_radius;
    const Eigen::Vector3d& p = target_[i];
    near_.clear();
    forEachNeighbour(p, params_.neighbour_radius, [&](uint32_t j) {
        const double d2 = (target_[j] - p).squaredNorm();
        if (d2 <= r2) near_.emplace_back(d2, j);
    });
    if (near_.size() < std::size_t(k)) return false;
    const std::size_t n = std::size_t(k);
    std::partial_sort(near_.begin(), near_.begin() + n, near_.end());
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (std::size_t j = 0; j < n; ++j) c += target_[near_[j].second];
    c /= double(n);
    Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
    for (std::size_t j = 0; j < n; ++j) {
        const Eigen::Vector3d d = target_[near_[j].second] - c;
        C += d * d.transpose();
    }
    normals_[i] = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(C).eigenvectors().col(0);
    has_normal_[i] = kNormalFound;
    return true;
}

int ScanRegistration::nearest(const Eigen::Vector3d& p, double max_distance) const {
    double best = max_distance * max_distance;
    int found = -1;
    forEachNeighbour(p, max_distance, [&](uint32_t j) {
        const double d2 = (target_[j] - p).squaredNorm();
        if (d2 < best || (d2 == best && found >= 0 && int(j) < found)) {
            best = d2;
            found = int(j);
        }
    });
    return found;
}

Eigen::Isometry3d ScanRegistration::align(const std::vector<Eigen::Vector3d>& source,
                                          const Eigen::Isometry3d& guess) {
    const std::vector<Eigen::Vector3d> points = voxelFilter(source, params_.source_voxel);
    Eigen::Isometry3d T = guess;
    for (int it = 0; it < params_.max_iterations; ++it) {
        Eigen::Matrix<double, 6, 6> H = Eigen::Matrix<double, 6, 6>::Zero();
        Eigen::Matrix<double, 6, 1> g = Eigen::Matrix<double, 6, 1>::Zero();
        const double max_d =
            it < params_.coarse_iterations ? params_.coarse_distance : params_.fine_distance;
        int used = 0;
        for (const Eigen::Vector3d& p0 : points) {
            const Eigen::Vector3d p = T * p0;
            const int i = nearest(p, max_d);
            if (i < 0 || !normalAt(uint32_t(i))) continue;
            const Eigen::Vector3d& n = normals_[i];
            const double residual = n.dot(p - target_[i]);
            Eigen::Matrix<double, 6, 1> J;
            J << p.cross(n), n;
            H += J * J.transpose();
            g += J * residual;
            ++used;
        }
        last_used_ = used;
        if (used < 6) break;
        const Eigen::Matrix<double, 6, 1> dx = -H.ldlt().solve(g);
        Eigen::Isometry3d D = Eigen::Isometry3d::Identity();
        const double angle = dx.head<3>().norm();
        if (angle > 0) D.linear() = Eigen::AngleAxisd(angle, dx.head<3>() / angle).matrix();
        D.translation() = dx.tail<3>();
        T = D * T;
        if (dx.norm() < params_.converged_step) break;
    }
    return T;
}

Eigen::Isometry3d ScanOdometry::add(const std::vector<Eigen::Vector3d>& points) {
    if (!first_) {
        motion_ = registration_.align(points, motion_);
        pose_ = pose_ * motion_;
    }
    first_ = false;
    registration_.setTarget(points);
    return pose_;
}

}  // namespace travel
