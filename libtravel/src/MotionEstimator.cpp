// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/MotionEstimator.hpp"

#include <cmath>

namespace travel {
namespace {

/// Rotation vector of R (axis * angle), robust near identity.
Eigen::Vector3d logOf(const Eigen::Matrix3d& R) {
    const Eigen::AngleAxisd aa(R);
    return aa.axis() * aa.angle();
}

}  // namespace

Eigen::Matrix3d yawPitchRoll(double yaw, double pitch, double roll) {
    return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
            Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
            Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
        .toRotationMatrix();
}

void MotionEstimator::PoseStream::add(double t, const Eigen::Isometry3d& pose) {
    // A repeated time stamp would make a zero interval: keep the newer pose only.
    if (has_last && t > t_last) {
        previous = last, t_previous = t_last, has_previous = true;
    }
    last = pose, t_last = t, has_last = true;
}

bool MotionEstimator::PoseStream::differentiate(double t, double max_age, Eigen::Vector3d& v_robot,
                                                Eigen::Vector3d& w_robot) const {
    if (!has_last || !has_previous) return false;
    const double dt = t_last - t_previous;
    if (!(dt > 0) || dt > max_age || std::abs(t - t_last) > max_age) return false;
    // Expressed in the newer robot frame.
    v_robot = last.linear().transpose() * (last.translation() - previous.translation()) / dt;
    w_robot = logOf(previous.linear().transpose() * last.linear()) / dt;
    return true;
}

bool MotionEstimator::fresh(bool valid, double t_sample, double t) const {
    return valid && std::abs(t - t_sample) <= max_age_;
}

void MotionEstimator::addAttitude(double t, const Eigen::Matrix3d& world_R_robot) {
    attitude_ = {true, t, world_R_robot};
}

void MotionEstimator::addAngularVelocity(double t, const Eigen::Vector3d& w_robot) {
    gyro_ = {true, t, w_robot};
}

void MotionEstimator::addOdometryVelocity(double t, const Eigen::Vector3d& v_robot,
                                          const Eigen::Vector3d& w_robot) {
    odom_linear_ = {true, t, v_robot};
    odom_angular_ = {true, t, w_robot};
}

void MotionEstimator::addImu(double t, const Eigen::Matrix3d& robot_R_imu,
                             const ImuReading& reading) {
    std::optional<Eigen::Matrix3d> world_R_imu;
    if (reading.orientation) {
        const Eigen::Quaterniond& q = *reading.orientation;
        if (q.norm() > 1e-9 && std::isfinite(q.norm()))
            world_R_imu = q.normalized().toRotationMatrix();
    } else if (reading.roll && reading.pitch) {
        world_R_imu = yawPitchRoll(reading.yaw.value_or(0.0), *reading.pitch, *reading.roll);
    }
    if (world_R_imu && world_R_imu->allFinite())
        addAttitude(t, *world_R_imu * robot_R_imu.transpose());
    if (reading.angular_velocity && reading.angular_velocity->allFinite())
        addAngularVelocity(t, robot_R_imu * *reading.angular_velocity);
}

void MotionEstimator::addPlanarOdometry(double t, double x, double y, double phi,
                                        const std::optional<Eigen::Vector3d>& vx_vy_omega) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = yawPitchRoll(phi, 0, 0);
    pose.translation() = Eigen::Vector3d(x, y, 0);
    addOdometryPose(t, pose);
    if (vx_vy_omega) {
        const Eigen::Vector3d& v = *vx_vy_omega;
        addOdometryVelocity(t, Eigen::Vector3d(v.x(), v.y(), 0), Eigen::Vector3d(0, 0, v.z()));
    }
}

void MotionEstimator::addRobotPose(double t, const Eigen::Isometry3d& world_T_robot) {
    robot_poses_.add(t, world_T_robot);
}

void MotionEstimator::addOdometryPose(double t, const Eigen::Isometry3d& odom_T_robot) {
    odometry_poses_.add(t, odom_T_robot);
}

MotionEstimate MotionEstimator::estimateAt(double t) const {
    MotionEstimate out;

    // Velocities by source. Pose differencing prefers the 3-D robot poses over odometry.
    Eigen::Vector3d pose_v, pose_w;
    const bool have_pose_rates = robot_poses_.differentiate(t, max_age_, pose_v, pose_w) ||
                                 odometry_poses_.differentiate(t, max_age_, pose_v, pose_w);
    const bool have_gyro = fresh(gyro_.valid, gyro_.t, t);
    const bool have_odom = fresh(odom_linear_.valid, odom_linear_.t, t);
    switch (source_) {
        case VelocitySource::Auto:
            if (have_gyro)
                out.angular_velocity = gyro_.value;
            else if (have_odom)
                out.angular_velocity = odom_angular_.value;
            else if (have_pose_rates)
                out.angular_velocity = pose_w;
            if (have_odom)
                out.linear_velocity = odom_linear_.value;
            else if (have_pose_rates)
                out.linear_velocity = pose_v;
            break;
        case VelocitySource::Imu:
            if (have_gyro) out.angular_velocity = gyro_.value;
            if (have_odom) out.linear_velocity = odom_linear_.value;
            break;
        case VelocitySource::Poses:
            if (have_pose_rates) out.angular_velocity = pose_w, out.linear_velocity = pose_v;
            break;
        case VelocitySource::None:
            break;
    }

    // Attitude: the measured one, else the 3-D robot pose's; carried to t by the angular rate
    // (IMU samples and LiDAR frames are rarely simultaneous).
    double t_att = 0;
    Eigen::Matrix3d R;
    if (fresh(attitude_.valid, attitude_.t, t)) {
        R = attitude_.value, t_att = attitude_.t;
    } else if (fresh(robot_poses_.has_last, robot_poses_.t_last, t)) {
        R = robot_poses_.last.linear(), t_att = robot_poses_.t_last;
    } else {
        return out;
    }
    const Eigen::Vector3d w = have_gyro              ? gyro_.value
                              : out.angular_velocity ? *out.angular_velocity
                                                     : Eigen::Vector3d::Zero();
    const double dt = t - t_att;
    if (dt != 0 && w.norm() > 0) R = R * Eigen::AngleAxisd(w.norm() * dt, w.normalized());
    out.attitude = R;
    return out;
}

void MotionEstimator::reset() {
    // Flags only: the stored values are never read while their flag is false.
    attitude_.valid = gyro_.valid = odom_linear_.valid = odom_angular_.valid = false;
    robot_poses_.has_last = robot_poses_.has_previous = false;
    odometry_poses_.has_last = odometry_poses_.has_previous = false;
}

}  // namespace travel
