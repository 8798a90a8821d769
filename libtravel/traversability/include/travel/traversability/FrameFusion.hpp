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

/// World-frame rays of one frame: from `origin` (the sensor) to the end points.
struct RayEnds {
    Eigen::Vector3f origin = Eigen::Vector3f::Zero();
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

/// A voxel key: integer voxel coordinates (x, y, z), each in 0..65535, as OctoMap's OcTreeKey
/// (coordinate / resolution + 32768, floored). Packed into one integer: 16 bits per axis.
inline uint64_t packVoxelKey(uint32_t x, uint32_t y, uint32_t z) {
    return (uint64_t(x) << 32) | (uint64_t(y) << 16) | uint64_t(z);
}

/// One frame's update of a voxel occupancy map (OctoMap) the way fast mappers do it: every voxel
/// updated once per frame (not once per point), free space carved along one ray per distinct
/// end voxel, a voxel hit in this frame occupied even when other rays of the frame cross it
/// (occupied wins over free). Rays are walked in voxel-key space (Amanatides & Woo) and
/// deduplicated in a bitmap around the sensor, not by sorting every traversed key.
class VoxelUpdate {
  public:
    /// The frame's end voxels (packVoxelKey); the caller fills them (any order, duplicates
    /// allowed). Obstacle ends are marked occupied; far ends (rays cut at max_ray_length) free.
    std::vector<uint64_t> ground_ends, obstacle_ends, far_ends;

    void clear() { ground_ends.clear(), obstacle_ends.clear(), far_ends.clear(); }

    /// Casts every ground_stride-th distinct ground ray, every obstacle ray and every far ray
    /// (whose end voxel is free too) from `origin`, the sensor in key units (coordinate /
    /// resolution + 32768, not floored). "Distinct" and "every n-th" go by the order of a
    /// bitmap of the box the frame's rays span (blocks of 8^3 voxels, each in octree order; no
    /// sorting). Afterwards freeKeys() and occupiedKeys() (both distinct, in that order) are
    /// disjoint.
    void cast(std::size_t ground_stride, const Eigen::Vector3d& origin);

    const std::vector<uint64_t>& freeKeys() const { return free_keys_; }
    const std::vector<uint64_t>& occupiedKeys() const { return obstacle_ends; }

    /// A ray walked back from its end stops after this many voxels in a row already carved by
    /// this frame's earlier rays: the rest of its way to the sensor is shared with them. 8
    /// keeps 94.5 % of the free voxels of full rays on the HDL-64E drive at 55 % of the cost
    /// (docs/map.md).
    static constexpr int kMaxSeenInARow = 8;

  private:
    /// Marks the voxels from the origin's voxel up to (without) `end` as seen this frame.
    void castRay(const Eigen::Vector3d& origin, uint64_t end);
    /// The voxel's bit in seen_, -1 outside the box.
    int64_t bitOf(uint64_t key) const;
    /// The bit of the voxel (x, y, z) of the box: blocks of kBlock^3 voxels in x, y, z order,
    /// inside a block the three coordinates' bits interleaved (x lowest, as OctoMap numbers
    /// children), so that a scan lists each block's voxels in a depth-first walk's order.
    int64_t localBit(int64_t x, int64_t y, int64_t z) const {
        const int64_t block =
            ((x >> kBlockBits) * blocks_[1] + (y >> kBlockBits)) * blocks_[2] + (z >> kBlockBits);
        const int64_t m = kSpread[x & (kBlock - 1)] | (kSpread[y & (kBlock - 1)] << 1) |
                          (kSpread[z & (kBlock - 1)] << 2);
        return block * kBlockWords * 64 + m;
    }
    /// Lists the voxels set in `bits` (a bitmap of the box) in the bitmap's order into `keys`
    /// and clears `bits`.
    void takeKeys(std::vector<uint64_t>& bits, std::vector<uint64_t>& keys) const;
    /// Leaves each key of `keys` once, in the bitmap's order (ends_ is the scratch bitmap).
    void distinct(std::vector<uint64_t>& keys);
    void mark(uint64_t key);
    void unmark(uint64_t key);

    std::vector<uint64_t> free_keys_;
    static constexpr int kBlockBits = 3, kBlock = 1 << kBlockBits;
    static constexpr int64_t kBlockWords = int64_t(1) << (3 * kBlockBits - 6);
    /// kSpread[v]: the 3 bits of v at bit positions 0, 3, 6 (one axis of a Morton code).
    static constexpr int64_t kSpread[kBlock] = {0, 1, 8, 9, 64, 65, 72, 73};
    /// Bitmap of the voxels seen this frame: a box of size_ voxels (blocks_ blocks) from corner_.
    std::vector<uint64_t> seen_;
    std::vector<uint64_t> ends_;  ///< a bitmap of the box, empty between uses
    std::vector<uint64_t> rays_;  ///< the end voxels of the rays cast this frame
    int64_t corner_[3] = {0, 0, 0};
    int64_t size_[3] = {0, 0, 0}, blocks_[3] = {0, 0, 0};
};

}  // namespace travel
