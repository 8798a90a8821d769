// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The robot's recent motion from IMU, odometry and pose samples, queried at each LiDAR frame's
// time: its attitude (for levelling) and its linear and angular velocity (for deskew), all in
// the ROBOT frame. Pure Eigen and seconds on one clock; travel_mrpt::TravelFilter converts the
// MRPT observations into these samples, and robot-frame velocities into the sensor frame.
//
// Samples are fed in rawlog order; only the newest of each kind is kept (plus the previous pose
// of each pose stream, for differencing). A sample further than max_age from the query time is
// stale and ignored.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>

#include "travel/Config.hpp"

namespace travel {

struct MotionEstimate {
    /// Robot orientation in a gravity-aligned world (yaw arbitrary: only roll/pitch matter).
    std::optional<Eigen::Matrix3d> attitude;
    std::optional<Eigen::Vector3d> linear_velocity;   ///< robot frame [m/s]
    std::optional<Eigen::Vector3d> angular_velocity;  ///< robot frame [rad/s]
};

/// One IMU reading, each part optional (what the device reports), in the IMU frame.
struct ImuReading {
    std::optional<Eigen::Quaterniond> orientation;    ///< world <- IMU (need not be normalised)
    std::optional<double> roll, pitch, yaw;           ///< [rad], used when no orientation
    std::optional<Eigen::Vector3d> angular_velocity;  ///< gyro [rad/s]
};

/// Rz(yaw) Ry(pitch) Rx(roll) (MRPT's CPose3D convention).
Eigen::Matrix3d yawPitchRoll(double yaw, double pitch, double roll);

class MotionEstimator {
  public:
    void setVelocitySource(VelocitySource source) { source_ = source; }
    void setMaxAge(double seconds) { max_age_ = seconds; }

    /// Measured robot orientation (e.g. an IMU's, already moved to the robot frame).
    void addAttitude(double t, const Eigen::Matrix3d& world_R_robot);
    /// Measured robot angular velocity (gyro), robot frame.
    void addAngularVelocity(double t, const Eigen::Vector3d& w_robot);
    /// Measured robot-frame twist from wheel odometry: (vx, vy, 0) and (0, 0, omega).
    void addOdometryVelocity(double t, const Eigen::Vector3d& v_robot,
                             const Eigen::Vector3d& w_robot);
    /// An IMU reading: its attitude (orientation, else roll/pitch with yaw 0 when absent: the
    /// world yaw reference does not change roll/pitch) and its gyro, moved to the robot frame
    /// with the IMU's mounting rotation. Non-finite or degenerate parts are ignored.
    void addImu(double t, const Eigen::Matrix3d& robot_R_imu, const ImuReading& reading);
    /// Planar wheel odometry: pose (x, y, phi) and, when known, velocities (vx, vy, omega) in
    /// the robot frame.
    void addPlanarOdometry(double t, double x, double y, double phi,
                           const std::optional<Eigen::Vector3d>& vx_vy_omega);
    /// Robot pose in a world/map frame (3-D: its roll/pitch are also an attitude sample).
    void addRobotPose(double t, const Eigen::Isometry3d& world_T_robot);
    /// Odometry pose (planar, its own frame): used for differencing only, never as attitude.
    void addOdometryPose(double t, const Eigen::Isometry3d& odom_T_robot);

    /// The motion at time t under the configured velocity source. The attitude is the newest
    /// fresh sample, carried to t with the angular velocity when that is known.
    MotionEstimate estimateAt(double t) const;

    /// Forget every sample.
    void reset();

  private:
    struct PoseStream {
        bool has_last = false, has_previous = false;
        double t_last = 0, t_previous = 0;
        Eigen::Isometry3d last = Eigen::Isometry3d::Identity();
        Eigen::Isometry3d previous = Eigen::Isometry3d::Identity();
        void add(double t, const Eigen::Isometry3d& pose);
        /// Velocities from the last two poses, if both fresh for `t`.
        bool differentiate(double t, double max_age, Eigen::Vector3d& v_robot,
                           Eigen::Vector3d& w_robot) const;
    };
    template <class T>
    struct Sample {
        bool valid = false;
        double t = 0;
        T value{};
    };

    bool fresh(bool valid, double t_sample, double t) const;

    VelocitySource source_ = VelocitySource::Auto;
    double max_age_ = 0.5;
    Sample<Eigen::Matrix3d> attitude_;
    Sample<Eigen::Vector3d> gyro_;
    Sample<Eigen::Vector3d> odom_linear_, odom_angular_;
    PoseStream robot_poses_, odometry_poses_;
};

}  // namespace travel
