// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// One segmented frame into a traversability map, free of MRPT and OctoMap: its ground and
// obstacle points go into the TraversabilityGrid, and the end points of its rays are collected
// for the voxel map (CTraversabilityMap turns them into OctoMap keys and casts the rays,
// deduplicated by VoxelUpdate).
//
//   travel::RayEnds ends;                 // reused from frame to frame
//   travel::fuseFrame({aligned, result, R, t, time_s}, map, grid, ends);
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "travel/Config.hpp"
#include "travel/Preprocessing.hpp"
#include "travel/Result.hpp"
#include "travel/traversability/TraversabilityGrid.hpp"

namespace travel {

/// A segmented frame placed in the world: p_world = to_world * p_aligned + origin, where origin
/// is the sensor's position in the world.
struct PlacedFrame {
    const AlignedCloud& aligned;
    const Result& result;
    Eigen::Matrix3f to_world;
    Eigen::Vector3f origin;
    double time_s = 0;  ///< stamped on the grid cells the frame updates
};

/// World-frame ray end points of one frame.
struct RayEnds {
    std::vector<Eigen::Vector3f> ground, obstacle;  ///< within max_ray_length of the sensor
    /// Longer rays (ground or obstacle), cut at max_ray_length: they carve free space only.
    std::vector<Eigen::Vector3f> far;
    void clear() { ground.clear(), obstacle.clear(), far.clear(); }
};

/// Fuses the frame into `grid` (beginFrame ... endFrame) and fills `ends`. Ground points
/// first, so that non-ground points see this frame's ground heights too. A non-ground point's
/// height above the local ground is TRAVEL's (TerrainModel::heightAboveGround), else the
/// ground fused in its grid cell this frame, else its cluster's ground_z, else its aligned z
/// + result.sensor_height (the height the pipeline used: its estimate under `auto`). Below
/// map.obstacle_min_height it is neither ground nor obstacle (kerb faces, low vegetation: no ray);
/// up to obstacle_max_height it is a grid obstacle; every such point ends an obstacle ray.
void fuseFrame(const PlacedFrame& frame, const MapSection& map, TraversabilityGrid& grid,
               RayEnds& ends);

/// One frame's update of a voxel occupancy map (OctoMap) with every voxel touched once: one ray
/// per distinct end voxel (not per point), traversed voxels free unless hit in this frame.
/// Voxels are keys packed into one sortable integer by the caller.
class VoxelUpdate {
  public:
    /// The frame's end voxels; the caller fills them (any order, duplicates allowed).
    std::vector<uint64_t> ground_ends, obstacle_ends, far_ends;

    void clear() { ground_ends.clear(), obstacle_ends.clear(), far_ends.clear(); }

    /// Casts every ground_stride-th ground ray, every obstacle ray and every far ray (whose end
    /// was traversed too): castRay(end, keys) appends the voxels from the sensor to `end`.
    /// Afterwards freeKeys() and occupiedKeys() are sorted and disjoint.
    template <class CastRay>
    void cast(std::size_t ground_stride, CastRay&& castRay) {
        sortUnique(ground_ends), sortUnique(obstacle_ends), sortUnique(far_ends);
        free_keys_.clear();
        for (std::size_t k = 0; k < ground_ends.size(); k += ground_stride)
            castRay(ground_ends[k], free_keys_);
        for (uint64_t end : obstacle_ends) castRay(end, free_keys_);
        for (uint64_t end : far_ends) {
            castRay(end, free_keys_);
            free_keys_.push_back(end);
        }
        sortUnique(free_keys_);
        free_keys_.erase(std::remove_if(free_keys_.begin(), free_keys_.end(),
                                        [&](uint64_t k) {
                                            return std::binary_search(obstacle_ends.begin(),
                                                                      obstacle_ends.end(), k);
                                        }),
                         free_keys_.end());
    }
    const std::vector<uint64_t>& freeKeys() const { return free_keys_; }
    const std::vector<uint64_t>& occupiedKeys() const { return obstacle_ends; }

  private:
    static void sortUnique(std::vector<uint64_t>& v) {
        std::sort(v.begin(), v.end());
        v.erase(std::unique(v.begin(), v.end()), v.end());
    }
    std::vector<uint64_t> free_keys_;
};

}  // namespace travel
