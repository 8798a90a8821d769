// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// travel::fuseFrame and travel::VoxelUpdate (what CTraversabilityMap fuses per frame) and
// travel::ObstacleMemory (the obstacle sources' memory), without MRPT or OctoMap.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "travel/traversability/FrameFusion.hpp"
#include "travel/traversability/ObstacleMemory.hpp"

using travel::PointClass;

namespace {

/// Frame of a few points in the aligned frame, sensor 2 m above the world origin, no terrain
/// model (TRAVEL's ground heights unknown: the fallbacks decide).
struct TinyFrame {
    travel::AlignedCloud aligned;
    travel::Result result;
    TinyFrame() { result.sensor_height = 2.0; }  // as the pipeline that segmented it used

    void add(float x, float y, float z, PointClass label, uint32_t cluster = 0) {
        aligned.x.push_back(x), aligned.y.push_back(y), aligned.z.push_back(z);
        aligned.valid.push_back(label != PointClass::Invalid);
        result.labels.push_back(label);
        result.cluster_id.push_back(cluster);
    }
    travel::PlacedFrame placed() const {
        return {aligned, result, Eigen::Matrix3f::Identity(), Eigen::Vector3f(0, 0, 2), 10.0};
    }
};

}  // namespace

TEST(FrameFusion, GroundObstaclesAndRayEnds) {
    travel::MapSection map;  // 40 x 40 m, 0.2 m cells, obstacles 0.25..2 m, rays <= 30 m
    map.min_obstacle_points = 1;
    travel::TraversabilityGrid grid;
    grid.reset(map);
    TinyFrame f;
    f.add(1.01f, 0.01f, -2.0f, PointClass::Ground);     // ground at world z = 0
    f.add(1.05f, 0.05f, -1.2f, PointClass::NonGround);  // 0.8 m above that cell's ground
    f.add(1.09f, 0.09f, -1.9f, PointClass::NonGround);  // 0.1 m: neither (no ray)
    f.add(5.01f, 5.01f, -1.0f, PointClass::NonGround);  // no ground: 1 m above z = -sensor
    f.add(8.01f, 8.01f, 2.0f, PointClass::NonGround);   // 4 m high: ray, not a grid obstacle
    f.add(35.f, 0.f, -2.0f, PointClass::Ground);        // beyond max_ray_length
    f.add(2.f, 2.f, -2.0f, PointClass::Invalid);        // ignored
    travel::RayEnds ends;
    travel::fuseFrame(f.placed(), map, grid, ends);

    ASSERT_EQ(ends.ground.size(), 1u);
    EXPECT_TRUE(ends.ground[0].isApprox(Eigen::Vector3f(1.01f, 0.01f, 0.f)));
    ASSERT_EQ(ends.obstacle.size(), 3u);
    EXPECT_TRUE(ends.obstacle[2].isApprox(Eigen::Vector3f(8.01f, 8.01f, 4.f)));
    ASSERT_EQ(ends.far.size(), 1u);  // cut at 30 m from the sensor
    EXPECT_NEAR((ends.far[0] - Eigen::Vector3f(0, 0, 2)).norm(), 30.f, 1e-3f);

    const long ground_cell = grid.cellIndex(1.01, 0.01);
    EXPECT_NEAR(grid.groundHeight(ground_cell), 0.f, 1e-6f);
    EXPECT_EQ(grid.lastSeen(ground_cell), 10.0);
    EXPECT_TRUE(grid.observed(grid.cellIndex(5.01, 5.01)));
    EXPECT_FALSE(grid.observed(grid.cellIndex(8.01, 8.01)));
    EXPECT_NEAR(grid.meanGroundHeight(), 0.0, 1e-6);
    const auto counts = grid.stateCounts(map);
    EXPECT_EQ(counts[0] + counts[1] + counts[2], grid.cellCount());
}

TEST(FrameFusion, ClusterGroundIsTheFallbackWithoutGridGround) {
    travel::MapSection map;
    map.obstacle_min_height = 0.5;
    travel::TraversabilityGrid grid;
    grid.reset(map);
    TinyFrame f;
    travel::ClusterSummary cluster;
    cluster.id = 1;
    cluster.ground_z = -1.5f;  // the cluster stands on a ground 0.5 m above -sensor_height
    f.result.clusters.push_back(cluster);
    f.add(3.f, 3.f, -1.2f, PointClass::NonGround, 1);  // 0.3 above its cluster ground: skipped
    f.add(3.f, 3.f, -0.9f, PointClass::NonGround, 1);  // 0.6: obstacle
    travel::RayEnds ends;
    travel::fuseFrame(f.placed(), map, grid, ends);
    EXPECT_EQ(ends.obstacle.size(), 1u);
}

// The last fallback (aligned z + h_s) takes h_s from the result, i.e. the height the pipeline
// segmented with (its estimate under `auto`), never a configured fallback passed separately.
TEST(FrameFusion, LastFallbackUsesTheResultsSensorHeight) {
    travel::MapSection map;
    map.min_obstacle_points = 1;
    for (const double h : {2.0, 0.5}) {
        travel::TraversabilityGrid grid;
        grid.reset(map);
        TinyFrame f;
        f.result.sensor_height = h;
        f.add(5.01f, 5.01f, -1.0f, PointClass::NonGround);  // no ground anywhere: z + h_s
        travel::RayEnds ends;
        travel::fuseFrame(f.placed(), map, grid, ends);
        // h_s 2 m: 1 m above the ground, an obstacle; h_s 0.5 m: below the ground, no ray.
        EXPECT_EQ(ends.obstacle.size(), h > 1.0 ? 1u : 0u) << "h_s " << h;
    }
}

TEST(FrameFusion, VoxelUpdateTouchesEachVoxelOnceAndOccupiedWinsOverFree) {
    // Rays along +x from the sensor in voxel (1000, 2000, 3000) (key units, not floored).
    const auto key = [](uint32_t x) { return travel::packVoxelKey(x, 2000, 3000); };
    travel::VoxelUpdate update;
    update.ground_ends = {key(1010), key(1010), key(1008)};  // duplicates: one ray per voxel
    update.obstacle_ends = {key(1005), key(1005)};           // on the way to both ground ends
    update.far_ends = {key(990)};
    update.cast(/*ground_stride=*/1, Eigen::Vector3d(1000.5, 2000.5, 3000.5));

    EXPECT_EQ(update.occupiedKeys(), (std::vector<uint64_t>{key(1005)}));
    // Traversed voxels, the sensor's voxel and the far end included, the ground ends left out
    // (1008 is traversed by the ray to 1010), the hit voxel 1005 not free although crossed.
    std::vector<uint64_t> expected;
    for (uint32_t x = 990; x <= 1009; ++x)
        if (x != 1005) expected.push_back(key(x));
    std::vector<uint64_t> free = update.freeKeys();
    std::sort(free.begin(), free.end());
    EXPECT_EQ(free, expected);

    // The next frame: nothing hit there, the ray to 1010 frees 1005 again.
    update.clear();
    update.ground_ends = {key(1010)};
    update.cast(1, Eigen::Vector3d(1000.5, 2000.5, 3000.5));
    EXPECT_TRUE(update.occupiedKeys().empty());
    EXPECT_NE(std::find(update.freeKeys().begin(), update.freeKeys().end(), key(1005)),
              update.freeKeys().end());
}

TEST(FrameFusion, VoxelUpdateWalksDiagonalRaysWithoutGaps) {
    // A ray across x, y and z: every step to a face neighbour, the end voxel's neighbour last.
    travel::VoxelUpdate update;
    update.ground_ends = {travel::packVoxelKey(1020, 2013, 2990)};
    update.cast(1, Eigen::Vector3d(1000.3, 2000.6, 3000.2));
    std::vector<uint64_t> keys = update.freeKeys();
    std::sort(keys.begin(), keys.end());
    ASSERT_EQ(keys.size(), 20u + 13u + 10u);  // one voxel per boundary crossed, end left out
    EXPECT_TRUE(
        std::binary_search(keys.begin(), keys.end(), travel::packVoxelKey(1000, 2000, 3000)));
    EXPECT_FALSE(
        std::binary_search(keys.begin(), keys.end(), travel::packVoxelKey(1020, 2013, 2990)));
}

TEST(ObstacleMemory, RecallsNearObstaclesInTheCurrentRobotFrame) {
    travel::ObstacleMemory memory;
    memory.configure(/*max_age=*/10, /*radius=*/1.0);
    travel::ObstaclePointCloud out;
    out.push_back(0.5f, 0.f, 0.3f);  // near: remembered
    out.push_back(5.f, 0.f, 0.3f);   // beyond 2 * radius: not remembered
    memory.recallAndRemember(0, Eigen::Vector3d(0, 0, 0), out);
    EXPECT_EQ(out.size(), 2u);  // this frame's own points are left as they are

    // The robot turned left by 90 degrees in place: the point ahead is now to its right.
    out.clear();
    memory.recallAndRemember(1, Eigen::Vector3d(0, 0, M_PI / 2), out);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_NEAR(out.x[0], 0.f, 1e-6f);
    EXPECT_NEAR(out.y[0], -0.5f, 1e-6f);
    EXPECT_EQ(out.z[0], 0.3f);

    // Moved 2 m away: out of the radius, not recalled.
    out.clear();
    memory.recallAndRemember(2, Eigen::Vector3d(2, 0, 0), out);
    EXPECT_EQ(out.size(), 0u);

    // Back: recalled at age 10 (not older than max_age), forgotten at age 11.
    memory.recallAndRemember(10, Eigen::Vector3d(0, 0, 0), out);
    EXPECT_EQ(out.size(), 1u);
    out.clear();
    memory.recallAndRemember(11, Eigen::Vector3d(0, 0, 0), out);
    EXPECT_EQ(out.size(), 0u);
}

TEST(ObstacleMemory, NegativeMaxAgeMeansNoMemory) {
    travel::ObstacleMemory memory;
    memory.configure(-1, 1.0);
    travel::ObstaclePointCloud out;
    out.push_back(0.5f, 0.f, 0.3f);
    memory.recallAndRemember(0, Eigen::Vector3d::Zero(), out);
    out.clear();
    memory.recallAndRemember(1, Eigen::Vector3d::Zero(), out);
    EXPECT_EQ(out.size(), 0u);
}
