// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// What of a frame belongs in a static map (issue 19): everything but the objects the tracker
// (travel::Tracker) flags `moving`. A moving car would otherwise leave a trail of obstacle
// cells and occupied voxels along its path.
//
//   travel::Result scratch;   // reused from frame to frame
//   const travel::Result& fused = travel::withoutMovingClusters(result, scratch);
//   travel::fuseFrame({aligned, fused, R, t, time_s}, map, grid, ends);
#pragma once

#include "travel/Result.hpp"

namespace travel {

/// `result` itself when no cluster is flagged moving (nothing copied: the common case, and
/// always so without tracking); else a copy in `scratch` (its capacity reused: no allocation
/// once warm) whose non-ground points of moving clusters are relabelled Outlier, which map
/// fusion skips: they become neither obstacles nor rays. Class counts follow; cluster ids and
/// summaries are unchanged.
const Result& withoutMovingClusters(const Result& result, Result& scratch);

}  // namespace travel
