// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Above-ground object segmentation on synthetic scenes with instance ground truth.
// "Coverage" of an object: the largest share of its non-ground-labelled points inside one
// cluster; "purity": the share of that cluster belonging to the object. Thresholds are stated
// per test.
#include <gtest/gtest.h>

#include <map>

#include "SceneMetrics.hpp"
#include "travel/Pipeline.hpp"
#include "travel/sim/Scenes.hpp"
#include "travel/sim/SyntheticLidar.hpp"

namespace travel {
namespace {

constexpr double kSensorHeight = 1.73;

using test::ObjectScore;

struct Segmented {
    sim::Scan scan;
    Result result;
    ObjectScore score(uint32_t instance) const {
        return test::scoreObject(scan.gt, result.labels, result.cluster_id, instance);
    }
};

Segmented segment(const sim::Scene& scene, sim::LidarModel lidar, double yaw_deg = 0) {
    lidar.range_noise_sigma = 0.01;
    lidar.seed = 3;
    lidar.max_range = 80;
    Segmented out;
    out.scan =
        sim::scan(scene, lidar, sim::sensorPoseAt(scene, 0, 0, kSensorHeight, 0, 0, yaw_deg));
    Params params;
    params.sensor_height = kSensorHeight;
    Pipeline pipeline(params);
    pipeline.process(out.scan.cloud, {}, out.result);
    return out;
}

TEST(Clustering, PolesAreOneClusterAcrossRings) {
    const Segmented s = segment(sim::urbanObjects(), sim::LidarModel::hdl64());
    for (const uint32_t pole : {4u, 5u, 6u}) {
        const ObjectScore score = s.score(pole);
        ASSERT_GT(score.points, 30u) << "pole " << pole;
        EXPECT_GE(score.coverage, 0.95) << "pole " << pole << " split vertically";
        EXPECT_GE(score.purity, 0.95) << "pole " << pole;
    }
}

TEST(Clustering, WallHiddenBehindPoleIsOneCluster) {
    // Wall 8 (3 m high, 24 m ahead) is partly shadowed by pole 6: skipped linkage bridges it.
    const Segmented s = segment(sim::urbanObjects(), sim::LidarModel::hdl64());
    const ObjectScore wall = s.score(8);
    ASSERT_GT(wall.points, 200u);
    EXPECT_GE(wall.coverage, 0.95);
    EXPECT_GE(wall.purity, 0.95);
}

TEST(Clustering, TwoCarsOneMetreApartAreTwoClusters) {
    const Segmented s = segment(sim::urbanObjects(), sim::LidarModel::hdl64());
    const ObjectScore a = s.score(1), b = s.score(2);
    ASSERT_GT(a.points, 100u);
    ASSERT_GT(b.points, 100u);
    EXPECT_NE(a.best_cluster, b.best_cluster);
    EXPECT_GE(a.purity, 0.95);
    EXPECT_GE(b.purity, 0.95);
    EXPECT_GE(a.coverage, 0.9);
    EXPECT_GE(b.coverage, 0.9);
}

TEST(Clustering, ObjectAcrossTheAzimuthSeamIsOneCluster) {
    // Column 0 of the range image is at azimuth -180 deg: a car straight behind the sensor
    // straddles the seam.
    sim::Scene scene = sim::flatGround();
    sim::Box car;
    car.id = 1, car.centre = {-8.0, 0.0}, car.length = 4.5, car.width = 1.8, car.height = 1.5;
    scene.boxes = {car};
    for (const auto& lidar : {sim::LidarModel::hdl64(), sim::LidarModel::vlp16()}) {
        const Segmented s = segment(scene, lidar);
        bool left = false, right = false;  // points on both sides of the seam
        for (std::size_t i = 0; i < s.scan.gt.size(); ++i) {
            if (s.scan.gt.instance[i] != 1) continue;
            left |= s.scan.cloud.y[i] > 0, right |= s.scan.cloud.y[i] < 0;
        }
        ASSERT_TRUE(left && right);
        const ObjectScore score = s.score(1);
        // The main cluster holds points from both sides of the seam.
        bool cluster_left = false, cluster_right = false;
        for (std::size_t i = 0; i < s.scan.gt.size(); ++i) {
            if (s.result.cluster_id[i] != score.best_cluster) continue;
            cluster_left |= s.scan.cloud.y[i] > 0, cluster_right |= s.scan.cloud.y[i] < 0;
        }
        EXPECT_TRUE(cluster_left && cluster_right) << lidar.numBeams() << " beams";
        // Not 1.0: the roof (1.5 m high, sensor at 1.73 m) is hit at a grazing angle, its
        // rings 0.8 m behind the rear face, beyond T_vert.
        EXPECT_GE(score.coverage, 0.9) << lidar.numBeams() << " beams";
        EXPECT_GE(score.purity, 0.97);
    }
}

TEST(Clustering, LongRunAcrossTheSeamWithManyRunsAfterItIsOneCluster) {
    // A wall behind the sensor crosses the seam (azimuth 180 deg); fourteen poles in front of
    // it on the seam's late side create more than T_skip + 1 runs after the wall's run began.
    // The wall's run is still open at the end of the ring and must be linked across the seam.
    sim::Scene scene = sim::flatGround();
    sim::Wall wall;
    wall.id = 1, wall.a = {-20.0, -15.0}, wall.b = {-20.0, 15.0}, wall.thickness = 0.3;
    wall.height = 2.5;
    scene.walls = {wall};
    for (int k = 0; k < 14; ++k) {  // every ring sees them all: 14 runs after the wall's
        sim::Pole pole;
        pole.id = 10 + k, pole.centre = {-10.0, 0.6 + 0.45 * k}, pole.radius = 0.1;
        pole.height = 4.0;
        scene.poles.push_back(pole);
    }
    const Segmented s = segment(scene, sim::LidarModel::hdl64());
    const ObjectScore score = s.score(1);
    ASSERT_GT(score.points, 1000u);
    EXPECT_GE(score.coverage, 0.95);
    EXPECT_GE(score.purity, 0.95);
}

TEST(Clustering, SparseFarObjectIsFound) {
    // A car 53 m ahead, its rear facing the sensor: about 10 columns x 5 rings. (Seen at a
    // grazing angle, a car's side gives points 0.6-1 m apart along the ring, which no
    // distance threshold of T_horz's size links; the face towards the sensor is what is found.)
    sim::Scene scene = sim::flatGround();
    sim::Box car;
    car.id = 1, car.centre = {55.0, 0.0}, car.length = 4.5, car.width = 1.8, car.height = 1.5;
    scene.boxes = {car};
    const Segmented s = segment(scene, sim::LidarModel::hdl64());
    const ObjectScore score = s.score(1);
    ASSERT_GE(score.points, 10u) << "the sensor should see the far car";
    EXPECT_GE(score.coverage, 0.8);
    EXPECT_NE(score.best_cluster, 0u);
}

TEST(Clustering, EveryNonGroundPointIsClusteredOrInASmallCluster) {
    const Segmented s = segment(sim::mixed(), sim::LidarModel::hdl64());
    Params params;
    // Size of the union-find component of unclustered points is not observable from outside;
    // instead: every clustered point is non-ground, cluster ids are 1..K, each cluster has at
    // least min_cluster_size points, and the summaries agree with the labels.
    std::map<uint32_t, std::size_t> size;
    for (std::size_t i = 0; i < s.result.cluster_id.size(); ++i) {
        const uint32_t id = s.result.cluster_id[i];
        if (id == 0) continue;
        EXPECT_EQ(s.result.labels[i], PointClass::NonGround);
        ++size[id];
    }
    ASSERT_EQ(size.size(), s.result.clusters.size());
    ASSERT_FALSE(size.empty());
    EXPECT_EQ(size.rbegin()->first, size.size());
    for (const ClusterSummary& c : s.result.clusters) {
        EXPECT_EQ(c.num_points, size[c.id]);
        EXPECT_GE(c.num_points, static_cast<uint32_t>(params.min_cluster_size));
    }
    // Ids are ordered by each cluster's first point.
    for (std::size_t k = 1; k < s.result.clusters.size(); ++k)
        EXPECT_LT(s.result.clusters[k - 1].first_point, s.result.clusters[k].first_point);
}

TEST(Clustering, UnclusteredPointsBelongToTooSmallGroups) {
    // With min_cluster_size = 1 every non-ground point must get a cluster id.
    const sim::Scene scene = sim::mixed();
    sim::LidarModel lidar = sim::LidarModel::hdl64();
    lidar.max_range = 80;
    const sim::Scan scan =
        sim::scan(scene, lidar, sim::sensorPoseAt(scene, 0, 0, kSensorHeight, 0, 0, 0));
    Params params;
    params.min_cluster_size = 1;
    Pipeline pipeline(params);
    Result result;
    pipeline.process(scan.cloud, {}, result);
    std::size_t nonground = 0;
    for (std::size_t i = 0; i < scan.cloud.size(); ++i) {
        if (result.labels[i] != PointClass::NonGround) continue;
        ++nonground;
        EXPECT_NE(result.cluster_id[i], 0u) << "point " << i;
    }
    EXPECT_GT(nonground, 1000u);
}

TEST(Clustering, IdenticalIdsAcrossRunsAndInstances) {
    const sim::Scene scene = sim::urbanObjects();
    const sim::Scan scan = sim::scan(scene, sim::LidarModel::hdl64(),
                                     sim::sensorPoseAt(scene, 0, 0, kSensorHeight, 0, 0, 0));
    Params params;
    Pipeline first(params), second(params);
    Result a, b, c;
    first.process(scan.cloud, {}, a);
    first.process(scan.cloud, {}, b);
    second.process(scan.cloud, {}, c);
    EXPECT_EQ(a.cluster_id, b.cluster_id);
    EXPECT_EQ(a.cluster_id, c.cluster_id);
    EXPECT_GT(a.clusters.size(), 5u);
}

TEST(Clustering, SummariesDescribeACar) {
    const Segmented s = segment(sim::urbanObjects(), sim::LidarModel::hdl64());
    const ObjectScore car = s.score(3);  // the yawed car (30 deg) at (-12, -6)
    ASSERT_NE(car.best_cluster, 0u);
    const ClusterSummary& c = s.result.clusters[car.best_cluster - 1];
    // Seen from one side only, so the box is partial; its height and ground are exact.
    EXPECT_NEAR(c.height_above_ground, 1.5, 0.15);
    EXPECT_NEAR(c.ground_z, -kSensorHeight, 0.1);
    // Partial view (one side and one end at most): the box is no larger than the car and no
    // smaller than its width.
    EXPECT_LE(c.obb_extent.x(), 4.7);
    EXPECT_GE(c.obb_extent.x(), 1.5);
    EXPECT_LE(c.obb_extent.y(), c.obb_extent.x());
    EXPECT_NEAR(c.centroid.x(), -12.0, 2.5);
    EXPECT_NEAR(c.centroid.y(), -6.0, 2.5);
}

}  // namespace
}  // namespace travel
