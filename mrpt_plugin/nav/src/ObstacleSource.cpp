// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/ObstacleSource.hpp"

#include <mrpt/maps/CSimplePointsMap.h>

#include <chrono>
#include <cmath>

namespace travel_mrpt {

void ObstacleSource::setMemory(const travel::NavSection& nav) {
    nav.validate();
    std::lock_guard<std::mutex> lock(update_mutex_);
    memory_ = nav;
    past_.clear();
}

void ObstacleSource::update(const ObstacleFrame& frame) {
    std::lock_guard<std::mutex> lock(update_mutex_);
    work_.clear();
    compute(frame, work_);
    addMemory(frame, work_);
    work_.timestamp = frame.timestamp;
    {
        std::lock_guard<std::mutex> publish(publish_mutex_);
        std::swap(work_, published_);
        has_published_ = true;
    }
}

void ObstacleSource::addMemory(const ObstacleFrame& frame, ObstaclePoints& out) {
    if (!(memory_.memory_seconds > 0.0)) return;
    const auto max_age = std::chrono::duration_cast<mrpt::Clock::duration>(
        std::chrono::duration<double>(memory_.memory_seconds));
    while (!past_.empty() && frame.timestamp - past_.front().stamp > max_age) {
        spare_.push_back(std::move(past_.front().points));
        past_.pop_front();
    }
    const std::size_t fresh = out.size();
    const double r2 = memory_.memory_radius * memory_.memory_radius;
    const Eigen::Vector3d& now = frame.robotOdometry;
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
    r.stamp = frame.timestamp;
    r.odometry = now;
    for (std::size_t i = 0; i < fresh; ++i)
        if (out.x[i] * out.x[i] + out.y[i] * out.y[i] <= 4.0 * r2)
            r.points.push_back(out.x[i], out.y[i], out.z[i]);
    past_.push_back(std::move(r));
}

bool ObstacleSource::latest(ObstaclePoints& out) const {
    std::lock_guard<std::mutex> lock(publish_mutex_);
    if (!has_published_) return false;
    out.x.assign(published_.x.begin(), published_.x.end());
    out.y.assign(published_.y.begin(), published_.y.end());
    out.z.assign(published_.z.begin(), published_.z.end());
    out.timestamp = published_.timestamp;
    return true;
}

bool ObstacleSource::latest(mrpt::maps::CSimplePointsMap& out,
                            mrpt::Clock::time_point& stamp) const {
    std::lock_guard<std::mutex> lock(publish_mutex_);
    out.clear();
    if (!has_published_) return false;
    out.reserve(published_.size());
    for (std::size_t i = 0; i < published_.size(); ++i)
        out.insertPointFast(published_.x[i], published_.y[i], published_.z[i]);
    out.mark_as_modified();
    stamp = published_.timestamp;
    return true;
}

}  // namespace travel_mrpt
