// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel_mrpt/LabelledOutputs.hpp"

#include <mrpt/maps/CPointsMapXYZI.h>
#include <mrpt/obs/CObservationPointCloud.h>

#include "travel_mrpt/TravelFilter.hpp"

using mrpt::obs::CObservation;
using mrpt::obs::CObservationPointCloud;
using travel::PointClass;

namespace travel_mrpt {

namespace {

constexpr std::array<PointClass, 3> kOutputClasses = {PointClass::Ground, PointClass::NonGround,
                                                      PointClass::Outlier};
constexpr std::array<const char*, 3> kOutputSuffixes = {"_ground", "_nonground", "_outlier"};
constexpr const char* kLabelsSuffix = "_travel";

bool endsWith(const std::string& label, const char* suffix) {
    const std::size_t n = std::char_traits<char>::length(suffix);
    return label.size() > n && label.compare(label.size() - n, n, suffix) == 0;
}

}  // namespace

bool isTravelOutput(const CObservation& obs) {
    if (dynamic_cast<const CObservationTravelLabels*>(&obs)) return true;
    if (!dynamic_cast<const CObservationPointCloud*>(&obs)) return false;
    for (const char* suffix : kOutputSuffixes)
        if (endsWith(obs.sensorLabel, suffix)) return true;
    return false;
}

std::string travelOutputSource(const CObservation& output) {
    return output.sensorLabel.substr(0, output.sensorLabel.rfind('_'));
}

void LabelledOutputPool::add(const CObservation& source, const TravelFrame& frame,
                             bool plain_clouds, std::vector<CObservation::Ptr>& added) {
    if (labels_used_ == labels_.size()) labels_.push_back(CObservationTravelLabels::Create());
    auto& labels = *labels_[labels_used_];
    labels.assign(frame.cloud, frame.result, frame.alignedRotation);
    labels.sensorPose = frame.sensorPose;
    labels.sourceClass = source.GetRuntimeClass()->className;
    labels.timestamp = source.timestamp;
    labels.sensorLabel = source.sensorLabel + kLabelsSuffix;
    added.push_back(labels_[labels_used_++]);
    if (plain_clouds)
        for (const auto& cloud : fillClouds(source, frame)) added.push_back(cloud);
}

const LabelledOutputPool::CloudSet& LabelledOutputPool::fillClouds(const CObservation& source,
                                                                   const TravelFrame& frame) {
    if (clouds_used_ == clouds_.size()) {
        CloudSet set;
        for (auto& obs : set) {
            obs = CObservationPointCloud::Create();
            obs->pointcloud = mrpt::maps::CPointsMapXYZI::Create();
        }
        clouds_.push_back(std::move(set));
    }
    const CloudSet& set = clouds_[clouds_used_++];
    const travel::PointCloud& cloud = frame.cloud;
    const travel::Result& result = frame.result;

    // Counted here rather than taken from result.class_counts: the buffers are written
    // without bounds checks below, so their sizes must come from the labels themselves
    // (& 3 keeps any label value inside the arrays).
    std::array<std::size_t, 4> count_of_class{};
    for (PointClass c : result.labels) ++count_of_class[static_cast<int>(c) & 3];
    std::array<mrpt::maps::CPointsMapXYZI*, 4> map_of_class{};  // indexed by PointClass
    std::array<std::size_t, 4> next_index{};
    for (std::size_t k = 0; k < set.size(); ++k) {
        CObservationPointCloud& obs = *set[k];
        obs.timestamp = source.timestamp;
        obs.sensorLabel = source.sensorLabel + kOutputSuffixes[k];
        obs.sensorPose = frame.sensorPose;
        auto* map = static_cast<mrpt::maps::CPointsMapXYZI*>(obs.pointcloud.get());
        map->setSize(count_of_class[static_cast<int>(kOutputClasses[k])]);
        map_of_class[static_cast<int>(kOutputClasses[k])] = map;
    }
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        const int c = static_cast<int>(result.labels[i]) & 3;
        mrpt::maps::CPointsMapXYZI* map = map_of_class[c];
        if (!map) continue;  // invalid
        const std::size_t j = next_index[c]++;
        map->setPointFast(j, cloud.x[i], cloud.y[i], cloud.z[i]);
        map->setPointColor_fast(j, cloud.intensity[i], 0.f, 0.f);  // = intensity
    }
    return set;
}

}  // namespace travel_mrpt
