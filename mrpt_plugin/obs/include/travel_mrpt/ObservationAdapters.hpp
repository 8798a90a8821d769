// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// MRPT observations -> travel::PointCloud, in the SENSOR frame.
//
//   travel::PointCloud cloud;          // keep it alive: its buffers are reused frame after frame
//   mrpt::poses::CPose3D sensor_pose;  // pose of the sensor on the robot
//   std::string why;
//   if (travel_mrpt::toTravelCloud(*obs, cloud, sensor_pose, &why)) pipeline.process(cloud, ...);
//
// Supported: CObservationVelodyneScan, CObservationRotatingScan (Velodyne range images),
// CObservationPointCloud and CObservation3DRangeScan. Fields filled:
//   x, y, z     always, metres, sensor frame (x forward, z up for the Velodyne family)
//   intensity   when the observation has one (0 otherwise)
//   ring        Velodyne family only: 0 = lowest elevation beam (NOT the laser id)
//   time        Velodyne family only: seconds after the observation timestamp
//
// Only forward declarations of MRPT types here: MRPT headers cost seconds per translation unit.
#pragma once

#include <string>

#include "travel/PointCloud.hpp"

namespace mrpt::obs {
class CObservation;
class CObservationVelodyneScan;
class CObservationRotatingScan;
class CObservationPointCloud;
class CObservation3DRangeScan;
}  // namespace mrpt::obs
namespace mrpt::poses {
class CPose3D;
}

namespace travel_mrpt {

/// Converts any supported LiDAR observation. Returns false, leaving `out` empty and setting
/// *why_not (if given) to a one-line reason, for observations without 3-D LiDAR data (other
/// classes, a Velodyne scan without calibration, an empty range image ...) and for a sensorPose
/// that is not finite (NaN or inf).
/// `out` keeps its capacity: after the first frames no allocation happens.
bool toTravelCloud(const mrpt::obs::CObservation& obs, travel::PointCloud& out,
                   mrpt::poses::CPose3D& sensor_pose, std::string* why_not = nullptr);

/// True when every coordinate and angle of `pose` is finite (no NaN, no inf).
bool isFinitePose(const mrpt::poses::CPose3D& pose);

/// True for the observation classes toTravelCloud() understands (cheap: no conversion), except
/// TRAVEL's own outputs (isTravelOutput(): the per-class clouds travel-rawlog writes beside its
/// labels), which are not LiDAR frames: every consumer (TravelFilter, the map layer, the apps)
/// skips them through this test.
bool isLidarObservation(const mrpt::obs::CObservation& obs);

// ---- One function per class; toTravelCloud() dispatches to them. Same contract. ----

/// Decodes the raw packets with the observation's own calibration. Ring = rank of the laser's
/// verticalCorrection (laser ids are in firing order: VLP-16 id 1 is +1 deg, id 2 is -13 deg).
bool velodyneToTravelCloud(const mrpt::obs::CObservationVelodyneScan& obs, travel::PointCloud& out,
                           std::string* why_not = nullptr);

/// Rebuilds XYZ from the range image with the default Velodyne calibration named by
/// `lidarModel` (VLP-16, HDL-32E; or by row count when the model is unknown): MRPT 2.5 stores
/// no elevation table in this class. Handles MRPT 2.5's fromVelodyne() quirk of a columnCount
/// that is rowCount times too large. Ring = elevation rank of the row's laser.
bool rotatingScanToTravelCloud(const mrpt::obs::CObservationRotatingScan& obs,
                               travel::PointCloud& out, std::string* why_not = nullptr);

/// Any CPointsMap (loaded first if externally stored); intensity if it is a CPointsMapXYZI.
bool pointCloudObsToTravelCloud(const mrpt::obs::CObservationPointCloud& obs,
                                travel::PointCloud& out, std::string* why_not = nullptr);

/// The stored 3-D points if present, otherwise the range image unprojected with the depth
/// camera intrinsics (sensor frame: +x forward, +z up).
bool rangeScan3DToTravelCloud(const mrpt::obs::CObservation3DRangeScan& obs,
                              travel::PointCloud& out, std::string* why_not = nullptr);

}  // namespace travel_mrpt
