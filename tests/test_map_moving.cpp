// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Issue 19: CTraversabilityMap leaves the objects the tracker flags moving out of the static
// map (travel::withoutMovingClusters before fusion): a moving object leaves no obstacle cell and
// no occupied voxel, the same object parked leaves both.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <octomap/OcTree.h>

#include "travel/traversability/StaticScene.hpp"
#include "travel_mrpt/CTraversabilityMap.hpp"
#include "travel_mrpt/TravelFilter.hpp"

namespace {

using travel::PointClass;
using travel_mrpt::CellState;
using travel_mrpt::CTraversabilityMap;

/// A segmented frame in the aligned frame (here the world axes, the sensor 2 m above flat
/// ground): a ring of ground points and one clustered object, 1.2 m x 0.6 m x 1.5 m, at
/// (6, 0), that the tracker flagged `moving` or not.
struct ObjectFrame {
    travel::AlignedCloud aligned;
    travel_mrpt::TravelFrame frame;

    explicit ObjectFrame(bool moving) {
        for (float x = -10.f; x <= 10.f; x += 0.5f)
            for (float y = -10.f; y <= 10.f; y += 0.5f) add(x, y, -2.f, PointClass::Ground, 0);
        for (float x = 5.4f; x <= 6.6f; x += 0.1f)
            for (float y = -0.3f; y <= 0.3f; y += 0.1f)
                for (float z = -1.8f; z <= -0.5f; z += 0.1f) add(x, y, z, PointClass::NonGround, 1);
        travel::ClusterSummary& c = frame.result.clusters.emplace_back();
        c.id = 1;
        c.num_points = uint32_t(frame.result.count(PointClass::NonGround));
        c.centroid = {6.f, 0.f, -1.15f};
        c.ground_z = -2.f;
        c.track_id = 7;
        c.moving = moving;
        c.velocity = {moving ? 5.f : 0.f, 0.f, 0.f};
        frame.result.sensor_height = 2.0;
        frame.aligned = &aligned;
    }
    void add(float x, float y, float z, PointClass label, uint32_t cluster) {
        aligned.x.push_back(x), aligned.y.push_back(y), aligned.z.push_back(z);
        aligned.valid.push_back(1);
        frame.result.labels.push_back(label);
        frame.result.cluster_id.push_back(cluster);
        ++frame.result.class_counts[static_cast<int>(label)];
    }
};

/// Fuses the same frame three times with the sensor 2 m above the world origin.
void fuseThrice(CTraversabilityMap& map, const ObjectFrame& f) {
    for (int k = 0; k < 3; ++k) map.fuseFrame(f.frame, mrpt::poses::CPose3D(0, 0, 2, 0, 0, 0));
}

bool occupiedVoxelAt(const CTraversabilityMap& map, double x, double y, double z) {
    const octomap::OcTreeNode* node = map.octree().search(x, y, z);
    return node && map.octree().isNodeOccupied(node);
}

}  // namespace

TEST(MapMovingObjects, ParkedObjectIsAnObstacleMovingOneLeavesNoTrace) {
    CTraversabilityMap parked_map{travel_mrpt::TraversabilityMapOptions{}};
    fuseThrice(parked_map, ObjectFrame(false));
    EXPECT_EQ(parked_map.stateAt(6.0, 0.0), CellState::Obstacle);
    EXPECT_TRUE(occupiedVoxelAt(parked_map, 6.0, 0.0, 1.0));
    EXPECT_EQ(parked_map.stateAt(3.0, 3.0), CellState::Traversable);

    CTraversabilityMap moving_map{travel_mrpt::TraversabilityMapOptions{}};
    fuseThrice(moving_map, ObjectFrame(true));
    for (double x = 5.4; x <= 6.6; x += 0.1)
        for (double y = -0.3; y <= 0.3; y += 0.1) {
            EXPECT_NE(moving_map.stateAt(x, y), CellState::Obstacle) << x << ", " << y;
            for (double z = 0.2; z <= 1.5; z += 0.1)
                EXPECT_FALSE(occupiedVoxelAt(moving_map, x, y, z)) << x << ", " << y << ", " << z;
        }
    EXPECT_EQ(moving_map.stateAt(3.0, 3.0), CellState::Traversable);  // the ground still fused
}

TEST(MapMovingObjects, StaticPartRelabelsOnlyMovingClustersAndCopiesNothingOtherwise) {
    const ObjectFrame parked(false), moving(true);
    travel::Result scratch;
    EXPECT_EQ(&travel::withoutMovingClusters(parked.frame.result, scratch), &parked.frame.result);
    EXPECT_TRUE(scratch.labels.empty());

    const travel::Result& kept = travel::withoutMovingClusters(moving.frame.result, scratch);
    EXPECT_EQ(&kept, &scratch);
    const std::size_t object = moving.frame.result.count(PointClass::NonGround);
    EXPECT_EQ(kept.count(PointClass::NonGround), 0u);
    EXPECT_EQ(kept.count(PointClass::Outlier), object);
    EXPECT_EQ(kept.count(PointClass::Ground), moving.frame.result.count(PointClass::Ground));
    EXPECT_EQ(kept.cluster_id, moving.frame.result.cluster_id);
    for (std::size_t i = 0; i < kept.labels.size(); ++i)
        EXPECT_EQ(kept.labels[i],
                  moving.frame.result.cluster_id[i] ? PointClass::Outlier : PointClass::Ground);
}

TEST(MapMovingObjects, TheMapsFilterTracksWhenItsIniSaysSo) {
    // A CMultiMetricMap .ini section: the filter key and a tracking key beside the map's.
    mrpt::config::CConfigFileMemory ini(
        "[MAP_traversabilityMap_00_creationOpts]\ntrack_objects = true\nconfirm_hits = 2\n");
    travel_mrpt::TraversabilityMapOptions options;
    options.loadFromConfigFile(ini, "MAP_traversabilityMap_00_creationOpts");
    CTraversabilityMap map(options);
    EXPECT_TRUE(map.filter().options().track_objects);
    EXPECT_EQ(map.filter().options().tracking.confirm_hits, 2);
}
