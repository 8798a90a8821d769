// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/Attitude.hpp"

#include <mrpt/core/bits_math.h>
#include <mrpt/poses/CPose3D.h>

#include <Eigen/Geometry>

namespace travel_mrpt {

void setMountFromSensorPose(const mrpt::poses::CPose3D& sensor_pose, travel::Params& params) {
    params.mount_yaw_deg = mrpt::RAD2DEG(sensor_pose.yaw());
    // `auto` angles stay auto: the pipeline estimates them from the ground.
    if (!params.mount_pitch_deg.isAuto())
        params.mount_pitch_deg = mrpt::RAD2DEG(sensor_pose.pitch());
    if (!params.mount_roll_deg.isAuto()) params.mount_roll_deg = mrpt::RAD2DEG(sensor_pose.roll());
}

Eigen::Matrix3d levellingRotation(const mrpt::poses::CPose3D& robot_pose) {
    return (Eigen::AngleAxisd(robot_pose.pitch(), Eigen::Vector3d::UnitY()) *
            Eigen::AngleAxisd(robot_pose.roll(), Eigen::Vector3d::UnitX()))
        .toRotationMatrix();
}

void setVehicleAttitude(const mrpt::poses::CPose3D& robot_pose, travel::FrameInput& input) {
    input.vehicle_attitude = levellingRotation(robot_pose);
}

}  // namespace travel_mrpt
