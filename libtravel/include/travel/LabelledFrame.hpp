// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The TRAVEL result of one frame in a compact, self-contained form: the input points with their
// labels and cluster ids, the cluster summaries, the non-empty nodes of the terrain model and
// the stage timings. Meant to be stored (travel_mrpt::CObservationTravelLabels derives it and
// adds MRPT serialization and 3-D visualisation) and read back without the pipeline.
//
// Per-point vectors are indexed exactly like the input cloud (every point, invalid ones
// included). Points are in the sensor frame; the cluster summaries and the terrain model are in
// TRAVEL's levelled "aligned" frame (sensor origin, z up against gravity): alignedRotation maps
// sensor -> aligned.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <vector>

#include "travel/Clusters.hpp"
#include "travel/PointCloud.hpp"
#include "travel/Result.hpp"
#include "travel/TerrainModel.hpp"

namespace travel {

/// One non-empty tri-grid node of the terrain model, compactly.
struct TerrainNodeRecord {
    /// Index into travel::TerrainModel::nodes: 4 * (iy * cells_per_side + ix) + triangle.
    uint32_t index = 0;
    NodeClass node_class = NodeClass::Unknown;
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
/// the terrain model's.
struct TerrainSummary : TriGridGeometry {
    std::vector<TerrainNodeRecord> nodes;  ///< non-empty nodes, increasing index

    /// Replaces the content by `model`'s non-empty nodes (keeps capacity).
    void assign(const TerrainModel& model);
    std::size_t numTraversable() const;
    /// The node's triangle (triangleCorners) lifted onto its plane; false when the grid has
    /// no cells or a corner height is not finite.
    bool triangle3D(const TerrainNodeRecord& node, std::array<Eigen::Vector3f, 3>& out) const;
};

struct LabelledFrame {
    // ---- Per point, same order and count as the source cloud, sensor frame ----
    std::vector<float> x, y, z, intensity;
    /// travel::PointClass values (0 invalid, 1 ground, 2 non-ground, 3 outlier).
    std::vector<uint8_t> labels;
    /// 0 = no cluster, k > 0 = clusters[k - 1].
    std::vector<uint32_t> clusterId;

    /// One per cluster, clusters[k].id == k + 1 (aligned frame).
    std::vector<ClusterSummary> clusters;
    /// Terrain model (aligned frame).
    TerrainSummary terrain;
    /// Sensor -> aligned rotation of this frame (travel::Pipeline::aligned().rotation).
    Eigen::Matrix3f alignedRotation = Eigen::Matrix3f::Identity();
    StageTimings timings;

    /// Fills every field from libtravel output (keeps vector capacity: no allocation once
    /// warmed up). `cloud` is the sensor-frame input of Pipeline::process(). Throws
    /// std::invalid_argument when result and cloud sizes differ.
    void assign(const PointCloud& cloud, const Result& result,
                const Eigen::Matrix3f& aligned_rotation);

    /// Number of points with label `c`.
    std::size_t count(PointClass c) const;
    std::size_t size() const { return labels.size(); }

    /// Human-readable summary: class counts, the largest clusters, the terrain, the timings.
    void describe(std::ostream& o) const;
};

}  // namespace travel
