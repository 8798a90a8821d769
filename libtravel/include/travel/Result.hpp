// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "travel/Clusters.hpp"
#include "travel/MountEstimator.hpp"
#include "travel/PointCloud.hpp"
#include "travel/TerrainModel.hpp"

namespace travel {

/// Milliseconds of the calling thread's CPU time spent in each stage of the last frame (time
/// spent waiting for a core is not in them: time process() with a wall clock for its latency).
struct StageTimings {
    double preprocess = 0;     ///< validity, alignment, deskew
    double embedding = 0;      ///< tri-grid field: points to nodes
    double node_fitting = 0;   ///< node-wise PCA terrain model
    double graph_search = 0;   ///< B-TGS
    double ttmf = 0;           ///< corner fitting
    double labelling = 0;      ///< per-point labels (eq. 5)
    double ground_total = 0;   ///< sum of the above
    double range_image = 0;    ///< rings and columns (AOS, Sec. IV-A)
    double horizontal = 0;     ///< runs along rings, circular and skipped linkage
    double vertical = 0;       ///< merges across rings
    double clusters = 0;       ///< ids, size filter, summaries
    double objects_total = 0;  ///< sum of the four above
};

/// The result of one frame. Vectors are indexed like the input cloud: every input point has
/// exactly one label, nothing is dropped.
struct Result {
    std::vector<PointClass> labels;
    /// Cluster id per point, 0 = no cluster (filled by object segmentation).
    std::vector<uint32_t> cluster_id;
    /// One entry per cluster, ordered by id (clusters[k].id == k + 1).
    std::vector<ClusterSummary> clusters;
    TerrainModel terrain;
    StageTimings timings;

    /// Number of points per class, indexed by PointClass value.
    std::array<std::size_t, 4> class_counts{};
    /// News about the sensor mount, set on one frame only (Pipeline: `auto` values estimated,
    /// or configured ones far from the ground); show `mount.message` to the user.
    MountNote mount;
    /// h_s this frame was segmented with: Pipeline::params().sensor_height, i.e. the estimate
    /// once an `auto` height is estimated (not the configured fallback). Consumers that need
    /// the height above ground (FrameFusion, evaluation protocol A) read it here.
    double sensor_height = 0;

    std::size_t count(PointClass c) const { return class_counts[static_cast<std::size_t>(c)]; }
};

}  // namespace travel
