// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/traversability/ObstacleMemory.hpp"

#include <cmath>

namespace travel {

void ObstacleMemory::configure(int64_t max_age, double radius) {
    max_age_ = max_age;
    radius_ = radius;
    past_.clear();
}

void ObstacleMemory::recallAndRemember(int64_t time, const Eigen::Vector3d& odometry,
                                       ObstaclePointCloud& out) {
    if (max_age_ < 0) return;
    while (!past_.empty() && time - past_.front().time > max_age_) {
        spare_.push_back(std::move(past_.front().points));
        past_.pop_front();
    }
    const std::size_t fresh = out.size();
    const double r2 = radius_ * radius_;
    const Eigen::Vector3d& now = odometry;
    for (const Remembered& m : past_) {
        // Point seen from pose m.odometry -> odometry frame -> robot frame now.
        const double c0 = std::cos(m.odometry.z()), s0 = std::sin(m.odometry.z());
        const double c1 = std::cos(now.z()), s1 = std::sin(now.z());
        for (std::size_t i = 0; i < m.points.size(); ++i) {
            const double wx = m.odometry.x() + c0 * m.points.x[i] - s0 * m.points.y[i];
            const double wy = m.odometry.y() + s0 * m.points.x[i] + c0 * m.points.y[i];
            const double dx = wx - now.x(), dy = wy - now.y();
            if (dx * dx + dy * dy > r2) continue;
            out.push_back(static_cast<float>(c1 * dx + s1 * dy),
                          static_cast<float>(-s1 * dx + c1 * dy), m.points.z[i]);
        }
    }
    // Remember this frame's own obstacles (not the recalled ones: they are already stored).
    Remembered r;
    if (!spare_.empty()) {
        r.points = std::move(spare_.back());
        spare_.pop_back();
    }
    r.points.clear();
    r.time = time;
    r.odometry = now;
    for (std::size_t i = 0; i < fresh; ++i)
        if (out.x[i] * out.x[i] + out.y[i] * out.y[i] <= 4.0 * r2)
            r.points.push_back(out.x[i], out.y[i], out.z[i]);
    past_.push_back(std::move(r));
}

}  // namespace travel
