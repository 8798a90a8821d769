// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Ground Plane Fitting (GPF): Zermas, Izzat, Papanikolopoulos, "Fast segmentation of 3D point
// clouds: a paradigm on LiDAR data for autonomous vehicle applications", ICRA 2017, Sec. III-A.
// The scan is split into N_segs segments along x (the direction of travel); in each, the
// lowest point representative (LPR, mean z of the N_LPR lowest points) selects the seeds
// (z < LPR + Th_seeds), then N_iter times a plane is fitted to the selection by PCA and the
// points closer than Th_dist to it are selected again. One plane per segment.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "travel/Params.hpp"
#include "travel/PointCloud.hpp"
#include "travel/Preprocessing.hpp"

namespace travel::eval {

struct GpfOptions {
    int num_segments = 3;         ///< N_segs (paper: 3), split along x
    int num_iterations = 3;       ///< N_iter (paper: 3)
    int num_lpr = 20;             ///< N_LPR (paper: 20)
    double seed_threshold = 0.4;  ///< Th_seeds [m] (paper: 0.4)
    double dist_threshold = 0.2;  ///< Th_dist [m] (paper: 0.2)
    /// Not in the paper (ground / non-ground only): points more than this below their plane are
    /// Outlier, as in TRAVEL, so below-ground noise is neither ground nor clustered.
    double outlier_dist = 0.5;
    /// Not in the paper either, but in the widely used GPF implementations: points lower than
    /// this times sensor_height below the sensor (mirror reflections under the road) are kept
    /// out of the LPR and the seeds; one such cluster would otherwise become the plane.
    double noise_floor_factor = 1.5;
};

/// Least-squares plane through the points `indices` of `cloud` by PCA: normal = eigenvector
/// of the smallest eigenvalue of their covariance, oriented z-up. Returns (n, d) with
/// n.p + d = signed height above the plane, or false with fewer than 3 points.
bool fitPlanePca(const AlignedCloud& cloud, const std::vector<uint32_t>& indices,
                 Eigen::Vector4f& plane);

class GroundPlaneFitting {
  public:
    explicit GroundPlaneFitting(const GpfOptions& options = {});

    /// labels[i] for every point of `cloud`: Invalid (cloud.valid[i] == 0), Ground (signed
    /// distance to its segment's plane below Th_dist and above -outlier_dist), Outlier, or
    /// NonGround.
    void segment(const AlignedCloud& cloud, const Params& params, std::vector<PointClass>& labels);

    const GpfOptions& options() const { return options_; }
    /// Plane of each segment of the last frame (n.p + d), by increasing x.
    const std::vector<Eigen::Vector4f>& planes() const { return planes_; }

  private:
    GpfOptions options_;
    std::vector<uint32_t> order_;     // valid points, partitioned into segments along x
    std::vector<uint32_t> selected_;  // seeds, then the points within Th_dist
    std::vector<float> lowest_z_;     // scratch for the LPR
    std::vector<Eigen::Vector4f> planes_;
};

}  // namespace travel::eval
