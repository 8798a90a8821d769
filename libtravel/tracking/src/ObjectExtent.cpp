// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/tracking/ObjectExtent.hpp"

#include <algorithm>
#include <cmath>

namespace travel {

Eigen::Vector2d extentAlong(const FlatBox& box, double yaw) {
    const double c = std::abs(std::cos(box.yaw - yaw)), s = std::abs(std::sin(box.yaw - yaw));
    return {box.size.x() * c + box.size.y() * s, box.size.x() * s + box.size.y() * c};
}

void ObjectExtent::update(const FlatBox& visible) {
    if (!known_) {
        full_ = visible;
        known_ = true;
        return;
    }
    if (visible.size.x() >= 0.9 * full_.size.x()) {
        // A view of (nearly) the whole length: its axes are the better ones.
        full_.size = extentAlong(full_, visible.yaw).cwiseMax(visible.size);
        full_.yaw = visible.yaw;
    } else {
        full_.size = full_.size.cwiseMax(extentAlong(visible, full_.yaw));
    }
}

Eigen::Vector2d ObjectExtent::centreOf(const FlatBox& visible,
                                       const Eigen::Vector2d& sensor) const {
    if (!known_) return visible.centre;
    const Eigen::Vector2d seen = extentAlong(visible, full_.yaw);
    const Eigen::Vector2d axes[2] = {{std::cos(full_.yaw), std::sin(full_.yaw)},
                                     {-std::sin(full_.yaw), std::cos(full_.yaw)}};
    Eigen::Vector2d centre = visible.centre;
    for (int a = 0; a < 2; ++a) {
        const double missing = full_.size[a] - seen[a];
        if (missing <= 0) continue;
        const double away = (visible.centre - sensor).dot(axes[a]) >= 0 ? 1.0 : -1.0;
        centre += away * 0.5 * missing * axes[a];
    }
    return centre;
}

}  // namespace travel
