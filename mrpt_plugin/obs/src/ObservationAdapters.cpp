// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Dispatcher, generic point clouds and 3-D range cameras. The Velodyne family is in
// VelodyneAdapters.cpp.
#include "travel_mrpt/ObservationAdapters.hpp"

#include <mrpt/img/CImage.h>
#include <mrpt/maps/CPointsMap.h>
#include <mrpt/maps/CPointsMapXYZI.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CObservationRotatingScan.h>
#include <mrpt/obs/CObservationVelodyneScan.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>

#include "travel_mrpt/LabelledOutputs.hpp"
#include "travel_mrpt/MrptMessage.hpp"

namespace travel_mrpt {
namespace {

bool fail(std::string* why_not, const std::string& reason) {
    if (why_not) *why_not = reason;
    return false;
}

/// obs.load() (a no-op unless the data is stored in an external file, which MRPT reads from
/// CImage::getImagesPathBase(): RawlogReader sets it to the rawlog's "_Images" folder); false
/// with MRPT's reason, named as external data, when the file cannot be read.
bool loadExternal(const mrpt::obs::CObservation& obs, std::string* why_not) {
    try {
        obs.load();
        return true;
    } catch (const std::exception& e) {
        return fail(why_not, "its externally stored data cannot be loaded (external files folder " +
                                 mrpt::img::CImage::getImagesPathBase() +
                                 "): " + mrptMessage(e.what()));
    }
}

template <class Vec>
void assignXYZ(const Vec& xs, const Vec& ys, const Vec& zs, travel::PointCloud& out) {
    out.x.assign(xs.begin(), xs.end());
    out.y.assign(ys.begin(), ys.end());
    out.z.assign(zs.begin(), zs.end());
    out.intensity.assign(xs.size(), 0.f);
}

}  // namespace

bool isFinitePose(const mrpt::poses::CPose3D& pose) {
    for (const double v : {pose.x(), pose.y(), pose.z(), pose.yaw(), pose.pitch(), pose.roll()})
        if (!std::isfinite(v)) return false;
    return true;
}

bool isLidarObservation(const mrpt::obs::CObservation& obs) {
    using namespace mrpt::obs;
    return (dynamic_cast<const CObservationVelodyneScan*>(&obs) ||
            dynamic_cast<const CObservationRotatingScan*>(&obs) ||
            dynamic_cast<const CObservationPointCloud*>(&obs) ||
            dynamic_cast<const CObservation3DRangeScan*>(&obs)) &&
           !isTravelOutput(obs);
}

bool toTravelCloud(const mrpt::obs::CObservation& obs, travel::PointCloud& out,
                   mrpt::poses::CPose3D& sensor_pose, std::string* why_not) {
    using namespace mrpt::obs;
    out.clear();
    obs.getSensorPose(sensor_pose);
    if (!isFinitePose(sensor_pose))
        return fail(why_not, "its sensorPose is not finite: " + sensor_pose.asString());
    if (auto* velodyne = dynamic_cast<const CObservationVelodyneScan*>(&obs))
        return velodyneToTravelCloud(*velodyne, out, why_not);
    if (auto* rotating = dynamic_cast<const CObservationRotatingScan*>(&obs))
        return rotatingScanToTravelCloud(*rotating, out, why_not);
    if (auto* cloud = dynamic_cast<const CObservationPointCloud*>(&obs))
        return pointCloudObsToTravelCloud(*cloud, out, why_not);
    if (auto* range3d = dynamic_cast<const CObservation3DRangeScan*>(&obs))
        return rangeScan3DToTravelCloud(*range3d, out, why_not);
    return fail(why_not, "not a 3-D LiDAR observation");
}

bool pointCloudObsToTravelCloud(const mrpt::obs::CObservationPointCloud& obs,
                                travel::PointCloud& out, std::string* why_not) {
    out.clear();
    // Externally stored clouds (e.g. KITTI .bin) are read on demand.
    if (obs.isExternallyStored() && !loadExternal(obs, why_not)) return false;
    if (!obs.pointcloud) return fail(why_not, "point cloud observation without a point map");
    const mrpt::maps::CPointsMap& map = *obs.pointcloud;
    if (map.empty()) return fail(why_not, "empty point cloud");
    assignXYZ(map.getPointsBufferRef_x(), map.getPointsBufferRef_y(), map.getPointsBufferRef_z(),
              out);
    if (auto* xyzi = dynamic_cast<const mrpt::maps::CPointsMapXYZI*>(&map)) {
        const auto& intensity = xyzi->getPointsBufferRef_intensity();
        if (intensity.size() == out.size())
            out.intensity.assign(intensity.begin(), intensity.end());
    }
    return true;
}

bool rangeScan3DToTravelCloud(const mrpt::obs::CObservation3DRangeScan& obs,
                              travel::PointCloud& out, std::string* why_not) {
    out.clear();
    if (!loadExternal(obs, why_not)) return false;  // range images may be in external files
    if (obs.hasPoints3D && !obs.points3D_x.empty()) {
        if (obs.points3D_y.size() != obs.points3D_x.size() ||
            obs.points3D_z.size() != obs.points3D_x.size())
            return fail(why_not, "3-D range scan with inconsistent point arrays");
        assignXYZ(obs.points3D_x, obs.points3D_y, obs.points3D_z, out);
        return true;
    }
    if (!obs.hasRangeImage || obs.rangeImage.size() == 0)
        return fail(why_not, "3-D range scan without points or range image");

    // Reused across calls so that steady-state conversion does not allocate.
    thread_local mrpt::maps::CSimplePointsMap scratch;
    scratch.clear();
    // unprojectInto() takes a non-const observation only to cache its unprojection table;
    // the range data itself is not modified.
    const_cast<mrpt::obs::CObservation3DRangeScan&>(obs).unprojectInto(scratch);
    if (scratch.empty()) return fail(why_not, "3-D range scan without valid depths");
    assignXYZ(scratch.getPointsBufferRef_x(), scratch.getPointsBufferRef_y(),
              scratch.getPointsBufferRef_z(), out);
    return true;
}

}  // namespace travel_mrpt
