// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Test helpers: read MRPT's sample rawlogs and label their LiDAR observations with TRAVEL into
// CObservationTravelLabels (shared by the in-process tests and the round-trip writer).
#pragma once

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <sys/stat.h>
#include <functional>
#include <memory>
#include <string>

#include "travel/ParamsIO.hpp"
#include "travel/Pipeline.hpp"
#include "travel_mrpt/Attitude.hpp"
#include "travel_mrpt/CObservationTravelLabels.hpp"
#include "travel_mrpt/ObservationAdapters.hpp"

namespace travel_test {

/// Debian's mrpt-common datasets folder.
inline const std::string kMrptDatasets = "/usr/share/mrpt/datasets";
inline const std::string kVlp16Rawlog = kMrptDatasets + "/test_velodyne_VLP16.rawlog";
inline const std::string kRotScanRawlog = kMrptDatasets + "/rot_scan_velodyne.rawlog";

inline bool fileExists(const std::string& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

/// Calls `f` for every observation of a rawlog (observations or sensory-frame format).
inline void forEachObservation(const std::string& path,
                               const std::function<void(const mrpt::obs::CObservation::Ptr&)>& f) {
    mrpt::io::CFileGZInputStream file;
    if (!file.open(path)) throw std::runtime_error("cannot open rawlog " + path);
    auto archive = mrpt::serialization::archiveFrom(file);
    for (;;) {
        mrpt::serialization::CSerializable::Ptr object;
        try {
            object = archive.ReadObject();
        } catch (const mrpt::serialization::CExceptionEOF&) {
            return;
        }
        if (auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(object)) {
            f(obs);
        } else if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(object)) {
            for (const auto& o : *sf) f(o);
        }
    }
}

/// Labels LiDAR observations with TRAVEL, parameters from share/configs/mrpt_sample_vlp16.yaml
/// (the floor of both sample rawlogs is 2.24 m below the sensor), mount from the sensor pose.
class SampleLabeller {
  public:
    explicit SampleLabeller(const std::string& config_path) {
        travel::applyParamsFile(config_path, base_);
    }

    /// False (and `out` untouched) when `obs` holds no LiDAR data.
    bool label(const mrpt::obs::CObservation& obs, travel_mrpt::CObservationTravelLabels& out) {
        mrpt::poses::CPose3D sensor_pose;
        if (!travel_mrpt::toTravelCloud(obs, cloud_, sensor_pose)) return false;
        travel::Params params = base_;
        travel_mrpt::setMountFromSensorPose(sensor_pose, params);
        travel::Pipeline pipeline(params);
        pipeline.process(cloud_, {}, result_);
        out.assign(cloud_, result_, pipeline.aligned().rotation);
        out.sensorPose = sensor_pose;
        out.sourceClass = obs.GetRuntimeClass()->className;
        out.sensorLabel = obs.sensorLabel + "_travel";
        out.timestamp = obs.timestamp;
        return true;
    }

    const travel::PointCloud& cloud() const { return cloud_; }
    const travel::Result& result() const { return result_; }

  private:
    travel::Params base_;
    travel::PointCloud cloud_;
    travel::Result result_;
};

}  // namespace travel_test
