// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/traversability/FrameFusion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace travel {

void fuseFrame(const PlacedFrame& frame, const MapSection& map, TraversabilityGrid& grid,
               RayEnds& ends) {
    const AlignedCloud& a = frame.aligned;
    const Result& result = frame.result;
    const TerrainModel& terrain = result.terrain;
    const std::size_t n = std::min({a.x.size(), a.valid.size(), result.labels.size()});
    const float min_h = float(map.obstacle_min_height);
    const float max_h = float(map.obstacle_max_height);
    const float max_ray = float(map.max_ray_length);
    const float sensor_height = float(result.sensor_height);
    ends.clear();
    ends.origin = frame.origin;
    const auto addEnd = [&](const Eigen::Vector3f& p, std::vector<Eigen::Vector3f>& near_list) {
        const float range = (p - frame.origin).norm();
        if (range > max_ray)  // too long to trust its end: carve up to max_ray only
            ends.far.push_back(frame.origin + (p - frame.origin) * (max_ray / range));
        else
            near_list.push_back(p);
    };

    grid.beginFrame();
    for (std::size_t i = 0; i < n; ++i) {
        if (!a.valid[i] || result.labels[i] != PointClass::Ground) continue;
        const Eigen::Vector3f pa(a.x[i], a.y[i], a.z[i]);
        const Eigen::Vector3f pw = frame.to_world * pa + frame.origin;
        grid.addGround(pw.x(), pw.y(), pw.z(), terrain.groundSlopeDeg(pa.x(), pa.y()));
        addEnd(pw, ends.ground);
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (!a.valid[i] || result.labels[i] != PointClass::NonGround) continue;
        const Eigen::Vector3f pa(a.x[i], a.y[i], a.z[i]);
        const Eigen::Vector3f pw = frame.to_world * pa + frame.origin;
        float height = terrain.heightAboveGround(pa.x(), pa.y(), pa.z());
        if (!std::isfinite(height)) {
            const long cell = grid.cellIndex(pw.x(), pw.y());
            const uint32_t cluster = i < result.cluster_id.size() ? result.cluster_id[i] : 0;
            if (cell >= 0 && std::isfinite(grid.groundHeightThisFrame(cell)))
                height = pw.z() - grid.groundHeightThisFrame(cell);
            else if (cluster > 0 && cluster <= result.clusters.size() &&
                     std::isfinite(result.clusters[cluster - 1].ground_z))
                height = pa.z() - result.clusters[cluster - 1].ground_z;
            else
                height = pa.z() + sensor_height;
        }
        if (height < min_h) continue;
        if (height <= max_h) grid.addObstacle(pw.x(), pw.y());
        addEnd(pw, ends.obstacle);
    }
    grid.endFrame(frame.time_s, map);
}

namespace {

int64_t keyAxis(uint64_t key, int axis) {
    return int64_t((key >> (16 * (2 - axis))) & 0xFFFF);
}

}  // namespace

int64_t VoxelUpdate::bitOf(uint64_t key) const {
    int64_t i[3];
    for (int a = 0; a < 3; ++a) {
        i[a] = keyAxis(key, a) - corner_[a];
        if (i[a] < 0 || i[a] >= size_[a]) return -1;
    }
    return localBit(i[0], i[1], i[2]);
}

void VoxelUpdate::mark(uint64_t key) {
    const int64_t bit = bitOf(key);
    if (bit >= 0) seen_[std::size_t(bit >> 6)] |= uint64_t(1) << (bit & 63);
}

void VoxelUpdate::unmark(uint64_t key) {
    const int64_t bit = bitOf(key);
    if (bit >= 0) seen_[std::size_t(bit >> 6)] &= ~(uint64_t(1) << (bit & 63));
}

void VoxelUpdate::castRay(const Eigen::Vector3d& origin, uint64_t end) {
    // Amanatides & Woo, walked backwards: from the end voxel's centre towards the sensor,
    // always across the nearest voxel boundary, in bitmap indices. The end voxel itself is
    // left out, the sensor's voxel included (the voxels of OctoMap's computeRayKeys).
    int64_t key[3], stop[3], step[3];
    double t_max[3], t_delta[3];
    Eigen::Vector3d from, dir;
    for (int a = 0; a < 3; ++a) {
        key[a] = keyAxis(end, a) - corner_[a];
        stop[a] = int64_t(std::floor(origin[a])) - corner_[a];
        if (key[a] < 0 || key[a] >= size_[a]) return;  // not a ray of this frame's box
        from[a] = double(key[a]) + 0.5;
        dir[a] = origin[a] - double(corner_[a]) - from[a];
    }
    const double length = dir.norm();
    if (!(length > 0)) return;
    dir /= length;
    for (int a = 0; a < 3; ++a) {
        step[a] = dir[a] > 0 ? 1 : (dir[a] < 0 ? -1 : 0);
        if (step[a] == 0) {
            t_max[a] = t_delta[a] = std::numeric_limits<double>::infinity();
            continue;
        }
        t_max[a] = 0.5 / std::abs(dir[a]);  // from a voxel centre to its boundary
        t_delta[a] = 1.0 / std::abs(dir[a]);
    }
    int seen_in_a_row = 0;
    while (key[0] != stop[0] || key[1] != stop[1] || key[2] != stop[2]) {
        const int a =
            t_max[0] < t_max[1] ? (t_max[0] < t_max[2] ? 0 : 2) : (t_max[1] < t_max[2] ? 1 : 2);
        if (t_max[a] > length) break;  // past the sensor: rounding, stop
        key[a] += step[a];
        t_max[a] += t_delta[a];
        const int64_t bit = localBit(key[0], key[1], key[2]);
        uint64_t& word = seen_[std::size_t(bit >> 6)];
        const uint64_t mask = uint64_t(1) << (bit & 63);
        if (word & mask) {
            // The rest of the way to the sensor has been carved by earlier rays of this frame
            // (they all converge there): stop, as fast mappers do (voxblox's
            // max_consecutive_ray_collisions).
            if (++seen_in_a_row >= kMaxSeenInARow) break;
        } else {
            seen_in_a_row = 0;
            word |= mask;
        }
    }
}

void VoxelUpdate::takeKeys(std::vector<uint64_t>& bits, std::vector<uint64_t>& keys) const {
    keys.clear();
    for (std::size_t w = 0; w < bits.size(); ++w) {
        if (!bits[w]) continue;
        const int64_t block = int64_t(w) / kBlockWords;
        const int64_t bx = block / (blocks_[1] * blocks_[2]), by = block / blocks_[2] % blocks_[1],
                      bz = block % blocks_[2];
        const int first = int(int64_t(w) % kBlockWords) * 64;
        for (uint64_t word = bits[w]; word; word &= word - 1) {
            const int m = first + __builtin_ctzll(word);  // x, y, z bits interleaved
            const auto axis = [m](int a) {
                return int64_t(((m >> a) & 1) | ((m >> (a + 2)) & 2) | ((m >> (a + 4)) & 4));
            };
            keys.push_back(packVoxelKey(uint32_t(corner_[0] + bx * kBlock + axis(0)),
                                        uint32_t(corner_[1] + by * kBlock + axis(1)),
                                        uint32_t(corner_[2] + bz * kBlock + axis(2))));
        }
        bits[w] = 0;
    }
}

void VoxelUpdate::distinct(std::vector<uint64_t>& keys) {
    for (uint64_t key : keys) {
        const int64_t bit = bitOf(key);  // inside the box: the box holds every end
        ends_[std::size_t(bit >> 6)] |= uint64_t(1) << (bit & 63);
    }
    takeKeys(ends_, keys);
}

void VoxelUpdate::cast(std::size_t ground_stride, const Eigen::Vector3d& origin) {
    // The box every ray of this frame stays in (its ends and the sensor): the bitmap covers
    // only it, a few metres high, not the whole sphere of max_ray_length.
    int64_t low[3], high[3];
    for (int a = 0; a < 3; ++a) low[a] = high[a] = int64_t(std::floor(origin[a]));
    for (const std::vector<uint64_t>* ends : {&ground_ends, &obstacle_ends, &far_ends})
        for (uint64_t end : *ends)
            for (int a = 0; a < 3; ++a)
                low[a] = std::min(low[a], keyAxis(end, a)),
                high[a] = std::max(high[a], keyAxis(end, a));
    for (int a = 0; a < 3; ++a) {
        corner_[a] = low[a] & ~int64_t(kBlock - 1);  // blocks aligned with OctoMap nodes
        blocks_[a] = (high[a] - corner_[a]) / kBlock + 1;
        size_[a] = blocks_[a] * kBlock;
    }
    const std::size_t words = std::size_t(blocks_[0] * blocks_[1] * blocks_[2] * kBlockWords);
    seen_.assign(words, 0);
    ends_.assign(words, 0);
    // One ray per distinct end voxel, found with a bitmap instead of sorting the ~100k ends.
    distinct(ground_ends), distinct(obstacle_ends), distinct(far_ends);
    rays_.clear();
    for (std::size_t k = 0; k < ground_ends.size(); k += std::max<std::size_t>(1, ground_stride))
        rays_.push_back(ground_ends[k]);
    rays_.insert(rays_.end(), obstacle_ends.begin(), obstacle_ends.end());
    rays_.insert(rays_.end(), far_ends.begin(), far_ends.end());
    for (uint64_t end : rays_) castRay(origin, end);

    for (uint64_t end : far_ends) mark(end);
    // The free voxels: those marked, minus the occupied ones, in the bitmap's order: the order
    // of a depth-first walk of the OctoMap inside each block.
    for (uint64_t end : obstacle_ends) unmark(end);
    takeKeys(seen_, free_keys_);
}

void VoxelLogOdds::add(const std::vector<uint64_t>& keys, float delta, float min, float max,
                       BlockFill fill, void* context) {
    for (uint64_t key : keys) {
        const uint64_t corner = cornerOf(key);
        if (corner != last_corner_) {  // keys come block by block (VoxelUpdate's order)
            auto [it, inserted] = blocks_.try_emplace(corner);
            last_ = &it->second, last_corner_ = corner;
            if (inserted) fill(context, corner, last_->value);
            if (!last_->listed) changed_.push_back(corner), last_->listed = true;
        }
        const int index = localIndex(key);
        // OcTree::updateNodeLogOdds: add, then clamp.
        float& value = last_->value[index];
        value += delta;
        if (value < min) value = min;
        if (value > max) value = max;
        last_->changed[index >> 6] |= uint64_t(1) << (index & 63);
    }
}

}  // namespace travel
