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
#include <iterator>
#include <unordered_map>
#include <utility>
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

/// The log-odds of every voxel a map has updated, in a flat store (blocks of 8^3 voxels in a
/// hash by block), for an occupancy map updated every frame but read seldom: the voxel map's
/// master copy, while the OctoMap is brought up to date only when someone reads it
/// (CTraversabilityMap::octree()). add() is OctoMap's update of a node, value += delta clamped
/// to [min, max] in float, so the values are OctoMap's; takeChanged() lists the voxels changed
/// since its last call in octree (depth-first) order, for one walk down the tree.
class VoxelLogOdds {
  public:
    /// Fills the 512 values of a block on its first update (the voxel map's values before
    /// the store held it: 0 for a voxel never seen), given the key of its lowest corner and
    /// `values` in the block's order (localIndex). Called once per block, not per voxel.
    using BlockFill = void (*)(void* context, uint64_t corner, float* values);

    /// Adds `delta` to each voxel of `keys` (packVoxelKey, distinct), clamped to [min, max].
    void add(const std::vector<uint64_t>& keys, float delta, float min, float max, BlockFill fill,
             void* context);
    /// Calls visit(key, value) for every voxel changed since the last call, in octree order,
    /// and forgets the changes.
    template <class Visit>
    void takeChanged(Visit&& visit);
    /// Forgets every value (the voxel map was replaced or cleared).
    void clear() { blocks_.clear(), changed_.clear(), last_ = nullptr, last_corner_ = ~0ull; }
    bool hasChanges() const { return !changed_.empty(); }
    std::size_t blocks() const { return blocks_.size(); }

    static constexpr int kBlockBits = 3, kBlock = 1 << kBlockBits;
    /// A voxel's index in its block: x, y, z bits interleaved (x lowest), as OctoMap numbers
    /// children, so that increasing indices are a depth-first walk.
    static int localIndex(uint64_t key) {
        return int(kSpread[(key >> 32) & 7] | (kSpread[(key >> 16) & 7] << 1) |
                   (kSpread[key & 7] << 2));
    }
    static uint64_t cornerOf(uint64_t key) { return key & ~packVoxelKey(7, 7, 7); }
    /// The key of voxel `index` (localIndex) of the block at `corner`.
    static uint64_t keyAt(uint64_t corner, int index) {
        const auto axis = [index](int a) {
            return uint32_t(((index >> a) & 1) | ((index >> (a + 2)) & 2) |
                            ((index >> (a + 4)) & 4));
        };
        return corner + packVoxelKey(axis(0), axis(1), axis(2));
    }

  private:
    static constexpr int kSpread[kBlock] = {0, 1, 8, 9, 64, 65, 72, 73};
    struct Block {
        float value[kBlock * kBlock * kBlock];
        uint64_t changed[kBlock * kBlock * kBlock / 64] = {};
        bool listed = false;  ///< in changed_
    };
    std::unordered_map<uint64_t, Block> blocks_;  ///< by corner key; nodes never move
    std::vector<uint64_t> changed_;               ///< corners of the blocks with changes
    Block* last_ = nullptr;                       ///< the block of the previous key
    uint64_t last_corner_ = ~0ull;
    std::vector<std::pair<uint64_t, uint64_t>> order_;  ///< takeChanged's scratch
};

template <class Visit>
void VoxelLogOdds::takeChanged(Visit&& visit) {
    // Blocks in depth-first order: their corner's x, y, z bits interleaved from the top.
    const auto morton = [](uint64_t corner) {
        uint64_t code = 0;
        for (int bit = 15; bit >= kBlockBits; --bit)
            code = (code << 3) | ((corner >> (32 + bit)) & 1) |
                   (((corner >> (16 + bit)) & 1) << 1) | (((corner >> bit) & 1) << 2);
        return code;
    };
    order_.clear();
    for (uint64_t corner : changed_) order_.emplace_back(morton(corner), corner);
    std::sort(order_.begin(), order_.end());
    for (const auto& [code, corner] : order_) {
        Block& block = blocks_.find(corner)->second;
        for (int w = 0; w < int(std::size(block.changed)); ++w) {
            for (uint64_t word = block.changed[w]; word; word &= word - 1) {
                const int index = w * 64 + __builtin_ctzll(word);
                visit(keyAt(corner, index), block.value[index]);
            }
            block.changed[w] = 0;
        }
        block.listed = false;
    }
    changed_.clear();
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
