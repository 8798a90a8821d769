// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/sim/TrafficSequence.hpp"

#include <cmath>

#include "travel/sim/Scenes.hpp"

namespace travel::sim {

Scene TrafficSequence::sceneAt(double t) const {
    Scene scene = background;
    for (const MovingBox& object : objects) {
        Box box = object.box;
        box.centre += object.velocity * t;
        scene.boxes.push_back(box);
    }
    return scene;
}

Eigen::Isometry3d TrafficSequence::sensorPoseAt(double t) const {
    // Straight until turn_start, then an arc of radius speed / yaw_rate.
    const double straight = std::min(t, ego.turn_start);
    double x = ego.speed * straight, y = 0.0, yaw = 0.0;
    const double turning = std::max(0.0, t - ego.turn_start);
    if (turning > 0 && ego.yaw_rate != 0) {
        yaw = ego.yaw_rate * turning;
        const double r = ego.speed / ego.yaw_rate;
        x += r * std::sin(yaw);
        y += r * (1 - std::cos(yaw));
    } else {
        x += ego.speed * turning;
    }
    return travel::sim::sensorPoseAt(background, x, y, ego.sensor_height, 0, 0, yaw / kDegToRad);
}

namespace {

MovingBox object(uint32_t id, double x, double y, double yaw_deg, double length, double width,
                 double height, Eigen::Vector2d velocity = {0, 0}) {
    MovingBox m;
    m.box.id = id;
    m.box.centre = {x, y};
    m.box.yaw_deg = yaw_deg;
    m.box.length = length;
    m.box.width = width;
    m.box.height = height;
    m.velocity = velocity;
    return m;
}

}  // namespace

TrafficSequence urbanTraffic() {
    TrafficSequence s;
    s.objects = {
        // Parked along both kerbs, and one across a driveway.
        object(1, 10.0, 5.5, 0, 4.5, 1.8, 1.5),
        object(2, 20.0, -6.0, 0, 4.5, 1.8, 1.5),
        object(3, 32.0, -6.5, 0, 4.2, 1.8, 1.6),
        object(4, 16.0, 14.0, 90, 4.5, 1.9, 1.5),
        object(5, 6.0, -9.5, 0, 0.5, 0.5, 1.7),  // a pedestrian standing
        // Moving: an oncoming car, a car crossing ahead, two pedestrians.
        object(11, 45.0, -2.5, 180, 4.5, 1.8, 1.5, {-7.0, 0.0}),
        object(12, 40.0, -24.0, 90, 4.5, 1.8, 1.5, {0.0, 6.0}),
        object(21, 2.0, -8.0, 0, 0.5, 0.5, 1.7, {1.4, 0.0}),
        object(22, 24.0, 9.0, 0, 0.5, 0.5, 1.8, {-1.2, 0.3}),
    };
    return s;
}

}  // namespace travel::sim
