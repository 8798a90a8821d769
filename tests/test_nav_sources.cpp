// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The obstacle sources on single scans of the default world, the thread-safe hand-over, the
// world reader's errors and the collision check.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <thread>

#include "NavPoints.hpp"
#include "nav/Collision.hpp"
#include "nav/Simulation.hpp"
#include "nav/World.hpp"
#include "travel/traversability/StaticScene.hpp"
#include "travel_mrpt/ObstacleSources.hpp"
#include "travel_mrpt/TravelObstacleSource.hpp"

using namespace travel::navsim;
using travel_test::countIn;

namespace {

const std::string kShare = TRAVEL_SHARE_DIR_FOR_TESTS;

struct Snapshot {
    travel::sim::Scan scan;
    travel_mrpt::ObstacleFrame frame;
    std::unique_ptr<SimTravel> travel;
};

/// One scan of `world` from the robot at (x, y, yaw), TRAVEL run on it, frame filled.
void snapshot(const World& world, double x, double y, double yaw, Snapshot& s) {
    SimOptions o;
    const auto fp = footprintFromConfig(kShare + "/configs/nav/reactive3d_travel.ini");
    double z = 0;
    const Eigen::Matrix3d R = robotAttitudeOnTerrain(world.scene, fp, x, y, yaw, z);
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = R;
    pose.translation() = Eigen::Vector3d(x, y, z);
    const Eigen::Isometry3d mount(Eigen::Translation3d(0, 0, o.sensor_height));
    travel::sim::scan(world.scene, o.lidar, pose * mount, s.scan);
    s.travel = std::make_unique<SimTravel>(o.travel);
    s.travel->process(s.scan.cloud, pose, mount, 0.0, s.frame);
    s.frame.sensorOnRobot = mount.cast<float>();
}

}  // namespace

// Robot at the foot of the ramp (x = 2.5 m, level, facing +x). The kerb (x 5.85..6.15,
// y -0.25..1.25) is 3.35-3.65 m ahead; the ramp surface starts 0.5 m ahead.
TEST(NavSources, TravelSeesTheKerbButNotTheRampRawSeesTheRamp) {
    const World world = loadWorld(kShare + "/worlds/ramp_kerb.world");
    Snapshot s;
    snapshot(world, 2.5, 0.0, 0.0, s);

    travel_mrpt::TravelObstacleSource travel_source;
    travel_source.update(s.frame);
    travel_mrpt::ObstaclePoints travel_points;
    ASSERT_TRUE(travel_source.latest(travel_points));
    const int travel_kerb = countIn(travel_points, 3.2, 3.8, -0.25, 1.25);
    // The ramp surface ahead, beside the kerb (|y| < 3, away from kerb and walls).
    const int travel_ramp =
        countIn(travel_points, 0.5, 3.2, -3.0, 3.0) + countIn(travel_points, 3.8, 6.0, -3.0, 3.0);
    auto raw = travel_mrpt::RobotFrameBandSource::raw();
    raw->update(s.frame);
    travel_mrpt::ObstaclePoints raw_points;
    ASSERT_TRUE(raw->latest(raw_points));
    const int raw_ramp = countIn(raw_points, 0.5, 3.2, -3.0, 3.0);
    std::printf("travel: kerb %d, ramp %d points; raw: ramp %d points\n", travel_kerb, travel_ramp,
                raw_ramp);
    EXPECT_GE(travel_kerb, 20);
    EXPECT_LE(travel_ramp, 10);
    EXPECT_GE(raw_ramp, 500);  // the raw source sees the ramp as a wall
    // TRAVEL's heights are above the local ground: the kerb's are within its 0.2 m (+ noise).
    for (std::size_t i = 0; i < travel_points.size(); ++i)
        if (travel_points.x[i] > 3.2 && travel_points.x[i] < 3.8 && travel_points.y[i] > -0.25 &&
            travel_points.y[i] < 1.25) {
            EXPECT_LT(travel_points.z[i], 0.35f);
        }
}

TEST(NavSources, HandOverNeverShowsAHalfWrittenSet) {
    // Frames whose points all share one z (k / 1000); a reader must always see a single z.
    travel_mrpt::RobotFrameBandSource source("band", -10.0, 10.0);
    std::atomic<bool> stop{false};
    std::atomic<int> mixed{0}, reads{0};
    std::thread reader([&] {
        travel_mrpt::ObstaclePoints p;
        while (!stop) {
            if (!source.latest(p)) continue;
            ++reads;
            for (std::size_t i = 1; i < p.size(); ++i)
                if (p.z[i] != p.z[0]) {
                    ++mixed;
                    break;
                }
        }
    });
    travel::PointCloud cloud;
    travel_mrpt::ObstacleFrame frame;
    frame.cloud = &cloud;
    for (int k = 1; k <= 300; ++k) {
        cloud.clear();
        for (int i = 0; i < 500 + k; ++i) cloud.push_back(1.f + 0.01f * i, 0.f, k / 1000.f);
        source.update(frame);
    }
    // Keep publishing the last frame until the reader has read a few sets (it may start late).
    while (reads.load() < 20) source.update(frame);
    stop = true;
    reader.join();
    EXPECT_EQ(mixed.load(), 0);
    EXPECT_GT(reads.load(), 0);
    travel_mrpt::ObstaclePoints last;
    ASSERT_TRUE(source.latest(last));
    EXPECT_EQ(last.size(), 800u);
    EXPECT_FLOAT_EQ(last.z[0], 0.3f);
}

// A box crossing 4 m ahead (x 3.6..4.4) from the right at 1 m/s, seen by a standing robot for
// 2.5 s (25 frames): with tracking it is flagged moving and the TRAVEL source hands its path
// over nav.predict_seconds (3 s) too, where nothing stands yet; its own points are not kept by
// the memory. Without tracking: only where it is, and the memory keeps a trail.
TEST(NavSources, MovingObjectIsPredictedAlongItsVelocityAndNotRemembered) {
    const World world0 =
        parseWorld("start 0 0 0\ngoal 10 0\nmover 4 -3.5 90 1.2 0.8 1.5 0 1.0\n", "crossing test");
    const auto run = [&](bool track) {
        SimOptions o;
        World world = world0;
        const Eigen::Isometry3d mount(Eigen::Translation3d(0, 0, o.sensor_height));
        SimTravel segmenter(o.travel, track, o.tracking);
        travel_mrpt::TravelObstacleSource source(o.nav);
        travel::NavSection memory = o.nav;
        memory.memory_seconds = 1.0, memory.memory_radius = 10.0;  // reaches the box
        source.setMemory(memory);
        travel::sim::Scan scan;
        travel_mrpt::ObstacleFrame frame;
        frame.sensorOnRobot = mount.cast<float>();
        for (int k = 0; k < 25; ++k) {
            const double t = 0.1 * k;
            placeMovers(world, t);
            travel::sim::scan(world.scene, o.lidar, mount, scan);
            frame.cloud = &scan.cloud;
            segmenter.process(scan.cloud, Eigen::Isometry3d::Identity(), mount, t, frame);
            frame.timestamp = mrpt::Clock::fromDouble(1.7e9 + t);
            source.update(frame);
        }
        travel_mrpt::ObstaclePoints points;
        EXPECT_TRUE(source.latest(points));
        return points;
    };
    // At t = 2.4 s the box spans y -1.7..-0.5; in 3 s its front reaches y 2.5. The tracker
    // flags it moving after moving_frames_on (5) fast frames: well before t = 1.4 s.
    const travel_mrpt::ObstaclePoints tracked = run(true), plain = run(false);
    EXPECT_GT(countIn(tracked, 3.0, 5.0, -1.7, -0.5), 0);  // where it is
    EXPECT_GT(countIn(plain, 3.0, 5.0, -1.7, -0.5), 0);
    EXPECT_GT(countIn(tracked, 3.0, 5.0, 0.2, 2.3), 20);  // where it goes
    EXPECT_EQ(countIn(plain, 3.0, 5.0, 0.2, 2.3), 0);
    // Where it was 0.3-1 s ago and no longer is: the memory's trail, kept only without tracking.
    EXPECT_GT(countIn(plain, 3.0, 5.0, -2.7, -2.1), 0);
    EXPECT_EQ(countIn(tracked, 3.0, 5.0, -2.7, -2.1), 0);
    // Nothing behind the box is predicted (the prediction runs along the velocity).
    EXPECT_EQ(countIn(tracked, 3.0, 5.0, -6.0, -3.0), 0);
}

// What the map fuses of a frame with a moving cluster: its points, and every ground or obstacle
// point within MovingFootprints::kMargin of its box, become outliers; the rest stays.
TEST(NavSources, WithoutMovingObjectsDropsTheMoversFootprint) {
    travel::Result r;
    travel::AlignedCloud a;
    const auto add = [&](float x, float y, travel::PointClass c, uint32_t id) {
        a.x.push_back(x), a.y.push_back(y), a.z.push_back(0.f), a.valid.push_back(1);
        r.labels.push_back(c), r.cluster_id.push_back(id);
        ++r.class_counts[static_cast<int>(c)];
    };
    add(5.0f, 0.0f, travel::PointClass::NonGround, 1);  // the mover's cluster
    add(5.0f, 0.6f, travel::PointClass::Ground, 0);     // its base: in the grown box
    add(5.0f, 1.2f, travel::PointClass::Ground, 0);     // beside it: outside
    add(9.0f, 0.0f, travel::PointClass::NonGround, 2);  // a parked box
    travel::ClusterSummary mover, parked;
    mover.id = 1, mover.moving = true;
    mover.obb_center = {5.f, 0.f, 0.5f}, mover.obb_extent = {1.2f, 0.8f, 1.5f};
    mover.obb_yaw = 0.f;
    parked.id = 2, parked.obb_center = {9.f, 0.f, 0.5f}, parked.obb_extent = {1.f, 1.f, 1.f};
    r.clusters = {mover, parked};
    travel::Result scratch;
    const travel::Result& kept = travel::withoutMovingObjects(r, a, scratch);
    ASSERT_EQ(&kept, &scratch);
    EXPECT_EQ(kept.labels[0], travel::PointClass::Outlier);
    EXPECT_EQ(kept.labels[1], travel::PointClass::Outlier);
    EXPECT_EQ(kept.labels[2], travel::PointClass::Ground);
    EXPECT_EQ(kept.labels[3], travel::PointClass::NonGround);
    EXPECT_EQ(kept.count(travel::PointClass::Outlier), 2u);
    EXPECT_EQ(kept.count(travel::PointClass::Ground), 1u);
    r.clusters[0].moving = false;  // nothing moves: the result itself, no copy
    EXPECT_EQ(&travel::withoutMovingObjects(r, a, scratch), &r);
}

TEST(NavWorld, MoversMoveAtTheirVelocity) {
    World w = parseWorld(
        "start 0 0 0\ngoal 10 0\nbox 2 2 0 1 1 1\nmover 4 -3 90 1.2 0.8 1.5 0.5 1\n", "mover test");
    ASSERT_EQ(w.movers.size(), 1u);
    EXPECT_TRUE(w.obstacles[w.movers[0].obstacle].moving);
    EXPECT_FALSE(w.obstacles[0].moving);
    placeMovers(w, 2.0);
    EXPECT_NEAR(w.scene.boxes[w.movers[0].box].centre.x(), 5.0, 1e-12);
    EXPECT_NEAR(w.scene.boxes[w.movers[0].box].centre.y(), -1.0, 1e-12);
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (const auto& p : w.obstacles[w.movers[0].obstacle].polygon) centre += p / 4.0;
    EXPECT_NEAR((centre - Eigen::Vector2d(5.0, -1.0)).norm(), 0.0, 1e-12);
    EXPECT_THROW(parseWorld("start 0 0 0\ngoal 1 0\nmover 4 -3 90 1.2 0.8 1.5 0.5\n", "m"),
                 std::runtime_error);
}

TEST(NavSources, TravelSourceRejectsAFrameWithoutResult) {
    travel::PointCloud cloud;
    cloud.push_back(1, 0, 0);
    travel_mrpt::ObstacleFrame frame;
    frame.cloud = &cloud;
    travel_mrpt::TravelObstacleSource source;
    EXPECT_THROW(source.update(frame), std::invalid_argument);
    travel_mrpt::ObstaclePoints p;
    EXPECT_FALSE(source.latest(p));
}

TEST(NavWorld, ErrorsNameFileLineAndExpectation) {
    try {
        parseWorld("start 0 0 0\ngoal 1 1\nbox 1 2 3\n", "w.world");
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("w.world:3"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("X Y YAW_DEG LENGTH WIDTH HEIGHT"), std::string::npos);
    }
    EXPECT_THROW(parseWorld("start 0 0 0\n", "w.world"), std::runtime_error);  // no goal
    EXPECT_THROW(parseWorld("start 0 0 x\ngoal 1 1\n", "w.world"), std::runtime_error);
    EXPECT_THROW(parseWorld("start 0 0 0\ngoal 1 1\nteapot 1\n", "w.world"), std::runtime_error);
    EXPECT_THROW(loadWorld("/nonexistent/x.world"), std::runtime_error);
    {  // a binary file given as a world is named, not echoed
        const std::string path = testing::TempDir() + "travel_test_binary.world";
        std::ofstream(path, std::ios::binary) << std::string("start\0\x01\xFF", 8);
        try {
            loadWorld(path);
            ADD_FAILURE() << "no error";
        } catch (const std::runtime_error& e) {
            EXPECT_NE(
                std::string(e.what()).find(path + ": not a text file (byte 0x00 at offset 5)"),
                std::string::npos)
                << e.what();
        }
        std::remove(path.c_str());
    }
    const World w = parseWorld("start 1 2 90\ngoal 3 4\nkerb 5 0 90 2 0.3 0.2\n", "w.world");
    ASSERT_EQ(w.obstacles.size(), 1u);
    ASSERT_EQ(w.scene.steps.size(), 1u);
    EXPECT_NEAR(w.start.z(), M_PI / 2, 1e-12);
    // The kerb raises the terrain by 0.2 m inside its rectangle only.
    EXPECT_NEAR(w.scene.terrainHeight(5.0, 0.9), 0.2, 1e-9);
    EXPECT_NEAR(w.scene.terrainHeight(5.0, 1.1), 0.0, 1e-9);
    EXPECT_NEAR(w.scene.terrainHeight(5.2, 0.0), 0.0, 1e-9);
}

TEST(NavCollision, FootprintDistances) {
    const std::vector<Eigen::Vector2d> square = {
        {0.3, -0.3}, {0.3, 0.3}, {-0.3, 0.3}, {-0.3, -0.3}};
    const World w = parseWorld("start 0 0 0\ngoal 9 0\nbox 2 0 0 1 1 1\npole 0 -1 0.1 1\n", "w");
    const Clearance at_start = clearance(placeFootprint(square, {0, 0, 0}), w);
    EXPECT_NEAR(at_start.distance, 0.6, 1e-9);  // the pole: 1 - 0.3 - 0.1
    EXPECT_EQ(at_start.nearest, "pole 1");
    EXPECT_NEAR(clearance(placeFootprint(square, {1.0, 0, 0}), w).distance, 0.2, 1e-9);
    EXPECT_EQ(clearance(placeFootprint(square, {1.3, 0, 0.3}), w).distance, 0.0);
}
