// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Ego-motion from consecutive scans when no pose is given: a compact point-to-plane ICP
// (Chen & Medioni 1992; linearised rotation, Low 2004) from the current scan to the previous one.
// The previous scan is voxel-filtered (target_voxel) and its normals come from the PCA of its
// `normal_neighbours` nearest points within neighbour_radius; the current scan is voxel-filtered
// more coarsely (source_voxel). Neighbours are found in a voxel hash of cell neighbour_radius
// (27 cells), so no k-d tree library is needed: Eigen only. Deterministic: the voxel filters sort
// their keys, nothing iterates a hash.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace travel {

/// Why these defaults: they are the ones share/bench/kitti_raw_pcd_poses.txt was made with
/// (HDL-64E at 10 Hz, urban speeds): 10 coarse iterations at 1 m correspondences, then 0.5 m.
struct RegistrationParams {
    double target_voxel = 0.2;      ///< [m] voxel of the previous scan
    double source_voxel = 0.4;      ///< [m] voxel of the current scan
    double neighbour_radius = 1.0;  ///< [m] normals and correspondences look this far (>= both)
    int normal_neighbours = 10;     ///< points of a normal's PCA, all within neighbour_radius
    double coarse_distance = 1.0;   ///< [m] correspondence gate of the first iterations
    double fine_distance = 0.5;     ///< [m] ... and of the later ones
    int coarse_iterations = 10;
    int max_iterations = 40;
    double converged_step = 1e-6;  ///< stop when the update (rad and m) is smaller

    /// The ego-motion of FrameTracker (non-ground points, 10 Hz): coarser voxels (0.5 m target,
    /// 1 m source; normals need 10 points within 1.5 m) and at most 15 iterations (5 coarse)
    /// with a convergence test. On the real drive: end point 0.08 m (xy) from the committed
    /// registration, ~10x less CPU than the defaults (docs/tracking.md).
    static RegistrationParams nonGroundOdometry() {
        RegistrationParams p;
        p.target_voxel = 0.5;
        p.source_voxel = 1.0;
        p.neighbour_radius = 1.5;
        p.coarse_iterations = 5;
        p.max_iterations = 15;
        p.converged_step = 1e-4;
        return p;
    }
};

/// Points averaged per voxel of side `voxel`, in increasing voxel-key order.
std::vector<Eigen::Vector3d> voxelFilter(const std::vector<Eigen::Vector3d>& points, double voxel);

class ScanRegistration {
  public:
    explicit ScanRegistration(const RegistrationParams& params = {}) : params_(params) {}

    /// The previous scan (its own frame): filtered, hashed, normals estimated.
    void setTarget(const std::vector<Eigen::Vector3d>& points);
    /// target_T_source: the pose of the current scan's frame in the previous scan's frame,
    /// refined from `guess`.
    Eigen::Isometry3d align(const std::vector<Eigen::Vector3d>& source,
                            const Eigen::Isometry3d& guess);
    /// Correspondences used in the last iteration of the last align().
    int lastCorrespondences() const { return last_used_; }

  private:
    /// Whether target point i has a normal (estimated on first use, then cached).
    bool normalAt(uint32_t i);
    /// Index of the nearest target point within `max_distance` of p, or -1.
    int nearest(const Eigen::Vector3d& p, double max_distance) const;
    int64_t cellKey(const Eigen::Vector3d& p) const;
    static int64_t cellKey(int64_t ix, int64_t iy, int64_t iz);
    /// f(target index) for every target point in the cells (of the 27 around p) that reach
    /// within `radius` (<= neighbour_radius) of p: a cell on one side is skipped when p is
    /// farther than radius from that face.
    template <class F>
    void forEachNeighbour(const Eigen::Vector3d& p, double radius, F&& f) const {
        const double s = params_.neighbour_radius;
        int64_t base[3];
        int lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
            const double cell = std::floor(p[a] / s);
            base[a] = int64_t(cell);
            const double offset = p[a] - cell * s;  // in [0, s)
            lo[a] = offset < radius ? -1 : 0;
            hi[a] = s - offset <= radius ? 1 : 0;
        }
        for (int dx = lo[0]; dx <= hi[0]; ++dx)
            for (int dy = lo[1]; dy <= hi[1]; ++dy)
                for (int dz = lo[2]; dz <= hi[2]; ++dz) {
                    const auto cell =
                        cells_.find(cellKey(base[0] + dx, base[1] + dy, base[2] + dz));
                    if (cell == cells_.end()) continue;
                    for (uint32_t j = cell->second.first; j < cell->second.second; ++j)
                        f(order_[j]);
                }
    }

    RegistrationParams params_;
    std::vector<Eigen::Vector3d> target_, normals_;
    enum : uint8_t { kNormalUnknown, kNormalFound, kNormalNone };
    std::vector<uint8_t> has_normal_;
    std::vector<std::pair<double, uint32_t>> near_;  ///< scratch of normalAt
    std::vector<uint32_t> order_;                    ///< target indices sorted by cell
    std::unordered_map<int64_t, std::pair<uint32_t, uint32_t>> cells_;  ///< key -> range in order_
    int last_used_ = 0;
};

/// Frame-to-frame odometry: each scan registered to the previous one, starting from the last
/// motion (constant velocity). Poses are of each scan's frame in the first scan's frame.
class ScanOdometry {
  public:
    explicit ScanOdometry(const RegistrationParams& params = {}) : registration_(params) {}
    /// The pose of this scan (identity for the first).
    Eigen::Isometry3d add(const std::vector<Eigen::Vector3d>& points);

  private:
    ScanRegistration registration_;
    Eigen::Isometry3d pose_ = Eigen::Isometry3d::Identity();
    Eigen::Isometry3d motion_ = Eigen::Isometry3d::Identity();
    bool first_ = true;
};

}  // namespace travel
