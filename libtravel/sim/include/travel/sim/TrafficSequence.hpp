// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// A scene that changes with time, for the tracker's evaluation: objects (cars, pedestrians)
// moving at constant velocity or parked, and an ego vehicle that drives and turns. Each
// object keeps its instance id in every frame, so the scans' ground truth (GroundTruth::instance)
// names the same object across frames.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "travel/sim/Scene.hpp"

namespace travel::sim {

/// An oriented box moving at constant velocity (zero: parked or standing). Its yaw is the
/// box's own (`box.yaw_deg`); box.centre is where it is at t = 0.
struct MovingBox {
    Box box;
    Eigen::Vector2d velocity{0.0, 0.0};  ///< [m/s] world frame
    bool moving() const { return velocity.squaredNorm() > 0; }
};

/// The ego vehicle: starts at the origin heading +x, drives at `speed`, and from `turn_start`
/// on turns at `yaw_rate` (counter-clockwise > 0); the sensor is `sensor_height` above the
/// terrain, level.
struct EgoPath {
    double speed = 8.0;           ///< [m/s]
    double turn_start = 1.0;      ///< [s]
    double yaw_rate = 0.25;       ///< [rad/s]
    double sensor_height = 1.73;  ///< [m]
};

struct TrafficSequence {
    Scene background;  ///< terrain and static objects
    std::vector<MovingBox> objects;
    EgoPath ego;
    double frame_period = 0.1;  ///< [s]
    int frames = 40;

    /// The background with every object placed at time t.
    Scene sceneAt(double t) const;
    /// Sensor pose in the world at time t (the scan is taken at that one pose).
    Eigen::Isometry3d sensorPoseAt(double t) const;
};

/// Flat street: four parked cars (ids 1-4), a standing pedestrian (5), an oncoming car (11), a
/// car crossing ahead (12) and two walking pedestrians (21, 22); the ego vehicle turns left
/// after 1 s. 40 frames at 10 Hz.
TrafficSequence urbanTraffic();

}  // namespace travel::sim
