// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// CObservationTravelLabels: the TRAVEL result of one LiDAR observation, as an MRPT observation
// that rawlogs can hold and MRPT viewers can draw (it derives mrpt::opengl::Visualizable, which
// RawLogViewer renders through getVisualizationInto()).
//
//   travel_mrpt::registerClasses();   // or load libtravel_mrpt_plugin.so into an MRPT app
//   auto labels = travel_mrpt::CObservationTravelLabels::Create();
//   labels->assign(cloud, result, pipeline.aligned().rotation);
//   labels->sensorPose = sensor_pose; labels->timestamp = obs.timestamp; ...
//   archive << *labels;
//
// Per-point vectors are indexed exactly like the source observation's cloud (every point,
// invalid ones included), so labels[i] belongs to the source's point i. Points are in the
// sensor frame; the cluster summaries and the terrain model are in TRAVEL's levelled "aligned"
// frame (sensor origin, z up against gravity): alignedRotation maps sensor -> aligned.
//
// Reading the public data members needs only this header (no constructor call, so no link
// dependency on travel_mrpt): a plugin-only reader may static_cast a deserialized object whose
// class name is CObservationTravelLabels::className.
#pragma once

#include <mrpt/obs/CObservation.h>
#include <mrpt/opengl/Visualizable.h>
#include <mrpt/poses/CPose3D.h>

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "travel/LabelledFrame.hpp"

namespace travel_mrpt {

using travel::TerrainNodeRecord;
using travel::TerrainSummary;

/// The frame's data (points, labels, clusters, terrain, timings) and its filling from libtravel
/// output are travel::LabelledFrame's; this class adds what MRPT needs: the sensor pose, the
/// source class, serialization and the 3-D view. assign() leaves sensorPose, sourceClass,
/// timestamp and sensorLabel to the caller.
class CObservationTravelLabels : public mrpt::obs::CObservation,
                                 public mrpt::opengl::Visualizable,
                                 public travel::LabelledFrame {
    DEFINE_SERIALIZABLE(CObservationTravelLabels, travel_mrpt)

  public:
    /// Upper bound on the point count accepted when deserializing (corrupt-input guard).
    static constexpr std::size_t kMaxPoints = 50'000'000;

    /// Pose of the sensor on the robot (as in the source observation).
    mrpt::poses::CPose3D sensorPose;
    /// Class name of the source observation, e.g. "mrpt::obs::CObservationVelodyneScan".
    std::string sourceClass;

    void getSensorPose(mrpt::poses::CPose3D& out_sensor_pose) const override {
        out_sensor_pose = sensorPose;
    }
    void setSensorPose(const mrpt::poses::CPose3D& new_sensor_pose) override {
        sensorPose = new_sensor_pose;
    }
    void getDescriptionAsText(std::ostream& o) const override;
    /// Points coloured by class / cluster at sensorPose, traversable nodes as translucent
    /// triangles, a wire box per cluster. Invalid points are not drawn. A tracked cluster
    /// (track_id != 0) takes its track's colour, travel::viz::clusterColour(cluster), so an
    /// object keeps its colour across frames; clusters with drawsVelocityArrow() get an arrow
    /// (a CArrow named "track <id>" in the CSetOfObjects "travel_velocity_arrows") from the top
    /// of the box to where the object will be kArrowSeconds later.
    void getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const override;

    /// The arrow spans the distance covered in this time [s].
    static constexpr float kArrowSeconds = 1.f;
    /// Tracked clusters slower than this [m/s] (and not flagged moving) get no arrow.
    static constexpr float kMinArrowSpeed = 0.1f;
    /// Moving clusters, and tracked ones at kMinArrowSpeed or faster.
    static bool drawsVelocityArrow(const travel::ClusterSummary& c);
};

/// Colours used by getVisualizationInto() (0xRRGGBB), the same as the bird's-eye pictures.
/// Clusters use travel::viz::clusterColour(cluster) (their track's colour when tracked).
constexpr uint32_t kGroundColour = 0x28A528;       // green
constexpr uint32_t kOutlierColour = 0x003CFF;      // blue
constexpr uint32_t kUnclusteredColour = 0x787878;  // grey: non-ground, in no cluster
constexpr uint32_t kNonGroundColour = 0xDC0000;    // red: non-ground when nothing is clustered

}  // namespace travel_mrpt
