// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The observations TRAVEL adds to a rawlog for one labelled LiDAR observation (travel-rawlog's
// output): a CObservationTravelLabels "<label>_travel" and, for readers without the plugin,
// three CObservationPointCloud "<label>_ground", "<label>_nonground", "<label>_outlier"
// (CPointsMapXYZI, same sensorPose and timestamp, original intensity; invalid points in none).
#pragma once

#include <mrpt/obs/CObservation.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "travel_mrpt/CObservationTravelLabels.hpp"

namespace mrpt::obs {
class CObservationPointCloud;
}

namespace travel_mrpt {

struct TravelFrame;

/// An observation TRAVEL writes: the labels object, or a per-class cloud.
bool isTravelOutput(const mrpt::obs::CObservation& obs);

/// The sensor label of the observation a TRAVEL output was made from ("velodyne_ground" ->
/// "velodyne").
std::string travelOutputSource(const mrpt::obs::CObservation& output);

/// The added observations are serialized as soon as their record is written, so the objects
/// (and their point buffers) are reused for the next records: call startRecord() per record;
/// a second LiDAR in the same record gets its own set.
class LabelledOutputPool {
  public:
    void startRecord() {
        clouds_used_ = 0;
        labels_used_ = 0;
    }

    /// Appends the outputs for `frame` (made from `source`) to `added`: the labels object, then
    /// (with plain_clouds) the three per-class clouds.
    void add(const mrpt::obs::CObservation& source, const TravelFrame& frame, bool plain_clouds,
             std::vector<mrpt::obs::CObservation::Ptr>& added);

  private:
    using CloudSet = std::array<std::shared_ptr<mrpt::obs::CObservationPointCloud>, 3>;
    const CloudSet& fillClouds(const mrpt::obs::CObservation& source, const TravelFrame& frame);

    std::vector<CloudSet> clouds_;
    std::size_t clouds_used_ = 0;
    std::vector<CObservationTravelLabels::Ptr> labels_;
    std::size_t labels_used_ = 0;
};

}  // namespace travel_mrpt
