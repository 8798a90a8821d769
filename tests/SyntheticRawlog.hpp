// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// A synthetic rawlog of a robot driving, turning, pitching and rolling through a street
// (flat road, kerbs and sidewalks, bumps, cars, poles, walls), for the filter tests and the
// travel-rawlog command-line tests. Records, in time order:
//   - CObservationRotatingScan "VLP16" (lidarModel "VLP16", 16 x columns range image in
//     rotatingScanToTravelCloud's layout: rows = laser ids in firing order, column c at azimuth
//     c * 360 / columns clockwise, time c * sweep_period / columns after obs.timestamp); each
//     sweep is ray-cast with the sensor moving column by column (travel::sim::scanMoving);
//   - CObservationIMU "IMU" (orientation quaternion and gyro, robot frame) at imu_rate_hz;
//   - CObservationOdometry "ODOMETRY" (planar pose and local velocities) at odometry_rate_hz.
// Per-point ground truth is kept in the decoded order of the adapter (column-major, rows in
// firing order, no-returns skipped), so truth[k].cls[i] describes point i of frame k as
// travel_mrpt::toTravelCloud returns it. Everything is seeded and deterministic.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "travel/PointCloud.hpp"
#include "travel/sim/Scene.hpp"

namespace mrpt::serialization {
class CSerializable;
}

namespace travel_test {

struct SyntheticRawlogOptions {
    int frames = 10;
    int columns = 900;          ///< VLP-16 azimuth steps per revolution (0.4 deg)
    double sweep_period = 0.1;  ///< [s]
    double speed = 12.0;        ///< [m/s]
    double yaw_rate = 0.2;      ///< [rad/s], turning left
    double pitch_amplitude_deg = 8.0, pitch_frequency_hz = 2.0;
    double roll_amplitude_deg = 6.0, roll_frequency_hz = 1.1;
    double imu_rate_hz = 100.0;
    double odometry_rate_hz = 50.0;
    double gyro_noise = 0.002;        ///< [rad/s] sigma
    double attitude_noise_deg = 0.1;  ///< sigma, per axis
    Eigen::Vector3d sensor_offset{0.3, 0.0,
                                  1.8};  ///< sensor on the robot (robot origin on the ground)
    double mount_pitch_deg = 0.0;        ///< sensor mount pitch on the robot
    double range_noise = 0.01;           ///< [m] sigma
    double start_time = 1.0e9;           ///< [s] MRPT clock of the first sweep
    uint32_t seed = 7;
};

/// Ground truth of one LiDAR frame, in the adapter's decoded order.
struct FrameTruth {
    std::vector<uint8_t> cls;        ///< travel::sim::GtClass (Ground 1, NonGround 2)
    std::vector<uint32_t> instance;  ///< object id, 0 for terrain
    travel::PointCloud points;       ///< the simulated points (sensor frame, ring, time)
};

struct SyntheticRawlog {
    std::vector<std::shared_ptr<mrpt::serialization::CSerializable>> records;  ///< time order
    std::vector<FrameTruth> truth;  ///< one per LiDAR record, in record order
    /// True robot pose (world) at each LiDAR record's timestamp (start of its sweep), in
    /// record order.
    std::vector<Eigen::Isometry3d> frame_poses;
};

/// The street the robot drives through (starts at (-20, 0) heading +x).
travel::sim::Scene movingRobotScene();

SyntheticRawlog makeSyntheticRawlog(const SyntheticRawlogOptions& options = {});

/// Writes the records as an "observations"-format rawlog (gz). Throws std::runtime_error
/// naming the path on failure.
void writeRawlog(const SyntheticRawlog& rawlog, const std::string& path);

/// Writes the records in the "SensoryFrame" format (gz): per LiDAR frame, a CActionCollection
/// then one CSensoryFrame holding the IMU / odometry records since the previous frame and the
/// LiDAR observation. Throws std::runtime_error naming the path on failure.
/// The CActionCollection is empty unless `odometry_actions`; then it holds one
/// CActionRobotMovement2D (Gaussian odometry model) with the planar pose increment of the true
/// trajectory since the previous LiDAR frame; the first one carries the increment from the
/// odometer's zero (the world origin) to the first frame, so composing the increments gives the
/// planar world poses of frame_poses (x, y, yaw), as the CObservationOdometry records do.
void writeSensoryFrameRawlog(const SyntheticRawlog& rawlog, const std::string& path,
                             bool odometry_actions = false);

}  // namespace travel_test
