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

#include "travel/Clusters.hpp"
#include "travel/PointCloud.hpp"
#include "travel/Result.hpp"
#include "travel/TerrainModel.hpp"

namespace travel_mrpt {

/// One non-empty tri-grid node of the terrain model, compactly.
struct TerrainNodeRecord {
    /// Index into travel::TerrainModel::nodes: 4 * (iy * cells_per_side + ix) + triangle.
    uint32_t index = 0;
    travel::NodeClass node_class = travel::NodeClass::Unknown;
    bool traversable = false;
    /// true: normal/d/mean are TTMF's refitted plane, false: the node-wise PCA plane.
    bool refitted = false;
    /// Plane normal . p + d = 0 (aligned frame).
    Eigen::Vector3f normal{0.f, 0.f, 1.f};
    float d = 0.f;
    /// TTMF corner heights (NaN where no traversable node voted).
    Eigen::Vector3f corner_z{0.f, 0.f, 0.f};
    Eigen::Vector3f mean{0.f, 0.f, 0.f};
};

/// The terrain model without its empty nodes and per-point bookkeeping. Its tri-grid geometry
/// (resolution, cells_per_side, origin_xy in the aligned frame; nodeAt, triangleCorners) is
/// libtravel's.
struct TerrainSummary : travel::TriGridGeometry {
    std::vector<TerrainNodeRecord> nodes;  ///< non-empty nodes, increasing index

    std::size_t numTraversable() const;
};

class CObservationTravelLabels : public mrpt::obs::CObservation, public mrpt::opengl::Visualizable {
    DEFINE_SERIALIZABLE(CObservationTravelLabels, travel_mrpt)

  public:
    /// Upper bound on the point count accepted when deserializing (corrupt-input guard).
    static constexpr std::size_t kMaxPoints = 50'000'000;

    /// Pose of the sensor on the robot (as in the source observation).
    mrpt::poses::CPose3D sensorPose;
    /// Class name of the source observation, e.g. "mrpt::obs::CObservationVelodyneScan".
    std::string sourceClass;

    // ---- Per point, same order and count as the source cloud, sensor frame ----
    std::vector<float> x, y, z, intensity;
    /// travel::PointClass values (0 invalid, 1 ground, 2 non-ground, 3 outlier).
    std::vector<uint8_t> labels;
    /// 0 = no cluster, k > 0 = clusters[k - 1].
    std::vector<uint32_t> clusterId;

    /// One per cluster, clusters[k].id == k + 1 (aligned frame).
    std::vector<travel::ClusterSummary> clusters;
    /// Terrain model (aligned frame).
    TerrainSummary terrain;
    /// Sensor -> aligned rotation of this frame (travel::Pipeline::aligned().rotation).
    Eigen::Matrix3f alignedRotation = Eigen::Matrix3f::Identity();
    travel::StageTimings timings;

    /// Fills every TRAVEL field from libtravel output (keeps vector capacity: no allocation
    /// once warmed up). `cloud` is the sensor-frame input of Pipeline::process(). Throws
    /// std::invalid_argument when result and cloud sizes differ. sensorPose, sourceClass,
    /// timestamp and sensorLabel are left to the caller.
    void assign(const travel::PointCloud& cloud, const travel::Result& result,
                const Eigen::Matrix3f& aligned_rotation);

    /// Number of points with label `c`.
    std::size_t count(travel::PointClass c) const;
    std::size_t size() const { return labels.size(); }

    void getSensorPose(mrpt::poses::CPose3D& out_sensor_pose) const override {
        out_sensor_pose = sensorPose;
    }
    void setSensorPose(const mrpt::poses::CPose3D& new_sensor_pose) override {
        sensorPose = new_sensor_pose;
    }
    void getDescriptionAsText(std::ostream& o) const override;
    /// Points coloured by class / cluster at sensorPose, traversable nodes as translucent
    /// triangles, a wire box per cluster. Invalid points are not drawn.
    void getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const override;
};

/// Colours used by getVisualizationInto() (0xRRGGBB), the same as the bird's-eye pictures.
/// Clusters use travel_mrpt::clusterColour(id).
constexpr uint32_t kGroundColour = 0x28A528;       // green
constexpr uint32_t kOutlierColour = 0x003CFF;      // blue
constexpr uint32_t kUnclusteredColour = 0x787878;  // grey: non-ground, in no cluster
constexpr uint32_t kNonGroundColour = 0xDC0000;    // red: non-ground when nothing is clustered

}  // namespace travel_mrpt
