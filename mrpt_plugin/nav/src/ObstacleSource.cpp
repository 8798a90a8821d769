// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/ObstacleSource.hpp"

#include <mrpt/maps/CSimplePointsMap.h>

#include <chrono>

namespace travel_mrpt {

void ObstacleSource::setMemory(const travel::NavSection& nav) {
    nav.validate();
    std::lock_guard<std::mutex> lock(update_mutex_);
    memory_ = nav;
    // In MRPT clock ticks; -1 (no memory) unless memory_seconds > 0.
    const auto max_age = std::chrono::duration_cast<mrpt::Clock::duration>(
        std::chrono::duration<double>(nav.memory_seconds));
    recall_.configure(nav.memory_seconds > 0.0 ? int64_t(max_age.count()) : -1, nav.memory_radius);
}

void ObstacleSource::update(const ObstacleFrame& frame) {
    std::lock_guard<std::mutex> lock(update_mutex_);
    work_.clear();
    transient_.clear();
    compute(frame, work_, transient_);
    recall_.recallAndRemember(frame.timestamp.time_since_epoch().count(), frame.robotOdometry,
                              work_);
    work_.x.insert(work_.x.end(), transient_.x.begin(), transient_.x.end());
    work_.y.insert(work_.y.end(), transient_.y.begin(), transient_.y.end());
    work_.z.insert(work_.z.end(), transient_.z.begin(), transient_.z.end());
    work_.timestamp = frame.timestamp;
    {
        std::lock_guard<std::mutex> publish(publish_mutex_);
        std::swap(work_, published_);
        has_published_ = true;
    }
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
