// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/ObstacleSources.hpp"

#include "travel_mrpt/TravelObstacleSource.hpp"

#include <cmath>
#include <stdexcept>

namespace travel_mrpt {

RobotFrameBandSource::RobotFrameBandSource(std::string name, double min_z, double max_z)
    : name_(std::move(name)), min_z_(min_z), max_z_(max_z) {
    if (!(min_z < max_z))
        throw std::invalid_argument(name_ + " obstacle source: min_z must be below max_z");
}

// max_z 3 m: above any robot's height slices (the navigator ignores higher points anyway).
std::unique_ptr<RobotFrameBandSource> RobotFrameBandSource::raw(double min_z) {
    return std::make_unique<RobotFrameBandSource>("raw", min_z, 3.0);
}

std::unique_ptr<RobotFrameBandSource> RobotFrameBandSource::heightThreshold(double min_z) {
    return std::make_unique<RobotFrameBandSource>("threshold", min_z, 3.0);
}

void TravelObstacleSource::compute(const ObstacleFrame& frame, ObstaclePoints& out,
                                   travel::ObstaclePointCloud& transient) {
    if (frame.result == nullptr || frame.aligned == nullptr)
        throw std::invalid_argument(
            "travel obstacle source: the frame has no TRAVEL result or aligned cloud");
    obstacles_.compute(*frame.result, *frame.aligned, frame.sensorOnRobot, out, &transient);
    obstacles_.predictMoving(*frame.result, *frame.aligned, frame.sensorOnRobot, transient);
}

void RobotFrameBandSource::compute(const ObstacleFrame& frame, ObstaclePoints& out,
                                   travel::ObstaclePointCloud& /*transient*/) {
    if (frame.cloud == nullptr) throw std::invalid_argument(name() + " obstacle source: no cloud");
    const travel::PointCloud& c = *frame.cloud;
    const Eigen::Matrix3f& R = frame.sensorOnRobot.linear();
    const Eigen::Vector3f t = frame.sensorOnRobot.translation();
    const float lo = static_cast<float>(min_z_), hi = static_cast<float>(max_z_);
    for (std::size_t i = 0; i < c.size(); ++i) {
        const Eigen::Vector3f p(c.x[i], c.y[i], c.z[i]);
        // Same validity as TRAVEL's pre-processing would use: finite and not a no-return.
        if (!p.allFinite() || (p.x() == 0.f && p.y() == 0.f && p.z() == 0.f)) continue;
        const Eigen::Vector3f q = R * p + t;
        if (q.z() >= lo && q.z() <= hi) out.push_back(q.x(), q.y(), q.z());
    }
}

}  // namespace travel_mrpt
