// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// MRPT poses -> libtravel's alignment inputs.
//
// libtravel rotates every point with R = R_level * R_mount (see travel/Preprocessing.hpp):
//   R_mount  sensor -> vehicle, from Params::mount_{yaw,pitch,roll}_deg, composed as
//            Rz(yaw) * Ry(pitch) * Rx(roll): exactly MRPT's CPose3D convention, so the
//            observation's sensorPose angles are copied as they are;
//   R_level  vehicle -> gravity-aligned with the vehicle heading, from
//            FrameInput::vehicle_attitude: the robot's roll and pitch (yaw removed).
// Together they are the sensor -> gravity-aligned rotation, i.e. the rotation of
// (robot pose without yaw) (+) sensorPose. When the robot attitude is unknown (plain rawlogs,
// odometry-only robots) leave vehicle_attitude unset: R_level = identity.
//
// sensor_height is NOT derived from sensorPose.z: MRPT's robot frame origin is not always on the
// ground (the sample rawlog's sensor is 0.09 m above the origin but 2.24 m above the floor).
#pragma once

#include <Eigen/Core>

#include "travel/Params.hpp"
#include "travel/Preprocessing.hpp"

namespace mrpt::poses {
class CPose3D;
}

namespace travel_mrpt {

/// Copies the rotation of `sensor_pose` (sensor on the robot) into params.mount_*_deg.
/// The translation is ignored: libtravel works in a sensor-centred frame.
void setMountFromSensorPose(const mrpt::poses::CPose3D& sensor_pose, travel::Params& params);

/// Rotation from the robot frame to a gravity-aligned frame with the robot's heading:
/// Ry(pitch) * Rx(roll) of `robot_pose` (its yaw and translation are ignored).
Eigen::Matrix3d levellingRotation(const mrpt::poses::CPose3D& robot_pose);

/// input.vehicle_attitude = levellingRotation(robot_pose).
void setVehicleAttitude(const mrpt::poses::CPose3D& robot_pose, travel::FrameInput& input);

}  // namespace travel_mrpt
