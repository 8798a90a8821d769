// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
// RawlogMotion (declared in RawlogReader.hpp); apart from the reader, which needs no filter.
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationIMU.h>
#include <mrpt/obs/CObservationOdometry.h>

#include "travel_mrpt/RawlogReader.hpp"
#include "travel_mrpt/TravelFilter.hpp"

namespace travel_mrpt {

bool RawlogMotion::process(const mrpt::serialization::CSerializable& record) {
    if (auto* imu = dynamic_cast<const mrpt::obs::CObservationIMU*>(&record)) {
        filter_.processImu(*imu);
    } else if (auto* odometry = dynamic_cast<const mrpt::obs::CObservationOdometry*>(&record)) {
        odometry_pose_ = mrpt::poses::CPose3D(odometry->odometry);
        has_odometry_ = true;
        filter_.processOdometry(*odometry);
    } else if (auto* actions = dynamic_cast<const mrpt::obs::CActionCollection*>(&record)) {
        if (auto move = actions->getBestMovementEstimation()) {
            action_pose_ = action_pose_ + mrpt::poses::CPose3D(move->poseChange->getMeanVal());
            ++actions_;
            filter_.processAction(*move, mrpt::poses::CPose2D(action_pose_));
        }
    } else {
        return false;
    }
    return true;
}

std::optional<mrpt::poses::CPose3D> RawlogMotion::robotPose() const {
    if (actions_) return action_pose_;
    if (has_odometry_) return odometry_pose_;
    return std::nullopt;
}

}  // namespace travel_mrpt
