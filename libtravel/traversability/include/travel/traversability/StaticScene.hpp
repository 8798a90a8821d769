// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// What of a frame belongs in a static map (issue 19): everything but the objects the tracker
// (travel::Tracker) flags `moving`. A moving car would otherwise leave a trail of obstacle
// cells and occupied voxels along its path.
//
//   travel::Result scratch;   // reused from frame to frame
//   const travel::Result& fused = travel::withoutMovingObjects(result, aligned, scratch);
//   travel::fuseFrame({aligned, fused, R, t, time_s}, map, grid, ends);
#pragma once

#include <Eigen/Core>
#include <vector>

#include "travel/Preprocessing.hpp"
#include "travel/Result.hpp"

namespace travel {

/// The footprints of the clusters flagged moving: each one's oriented box (xy, aligned frame)
/// grown by kMargin. A mover's points outside its cluster (too few to cluster, its lowest
/// points that TRAVEL called ground, the step those make) lie in it too. Buffers reused.
class MovingFootprints {
  public:
    /// [m] around a moving cluster's box.
    static constexpr float kMargin = 0.3f;
    void build(const std::vector<ClusterSummary>& clusters);
    bool empty() const { return boxes_.empty(); }
    /// (x, y) in the aligned frame lies in one of the footprints.
    bool contains(float x, float y) const;

  private:
    struct Box {
        Eigen::Vector2f centre;
        float cos_yaw, sin_yaw, half_length, half_width;
    };
    std::vector<Box> boxes_;
};

/// `result` itself when no cluster is flagged moving (nothing copied: the common case, and
/// always so without tracking); else a copy in `scratch` (its capacity reused: no allocation
/// once warm) whose non-ground points of moving clusters are relabelled Outlier, which map
/// fusion skips: they become neither obstacles nor rays. Class counts follow; cluster ids and
/// summaries are unchanged.
const Result& withoutMovingClusters(const Result& result, Result& scratch);

/// The same, and also every ground or non-ground point of `aligned` (the cloud `result`
/// labels) inside a MovingFootprints box relabelled Outlier: what the map fuses.
const Result& withoutMovingObjects(const Result& result, const AlignedCloud& aligned,
                                   Result& scratch);

}  // namespace travel
