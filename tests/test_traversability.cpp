// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// libtravel's traversability component without MRPT: the fused grid on its own, and the pose
// files (TUM, KITTI, calib.txt) with their error messages.
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "travel/Errors.hpp"
#include "travel/traversability/PoseFiles.hpp"
#include "travel/traversability/TravelObstacles.hpp"
#include "travel/traversability/TraversabilityGrid.hpp"

namespace {

std::string tempPath() {
    static int counter = 0;
    return (std::filesystem::temp_directory_path() /
            ("travel_test_traversability_" + std::to_string(::getpid()) + "_" +
             std::to_string(counter++)))
        .string();
}

TEST(TraversabilityGrid, OneUpdatePerCellAndFrame) {
    travel::TraversabilityGrid grid;
    grid.reset({0.0, 2.0, 0.0, 1.0, 0.5});
    travel::GridFusionParams fusion;
    EXPECT_EQ(grid.sizeX(), 4);
    EXPECT_EQ(grid.sizeY(), 2);
    EXPECT_EQ(grid.cellIndex(-0.1, 0.2), -1);
    EXPECT_EQ(grid.cellIndex(1.99, 0.99), 7);
    for (int frame = 0; frame < 2; ++frame) {
        grid.beginFrame();
        for (int i = 0; i < 50; ++i) grid.addGround(0.25, 0.25, 0.01f * (i % 3), 2.f);  // flat
        grid.addObstacle(1.25, 0.25);
        grid.addObstacle(1.25, 0.25);
        for (int i = 0; i < 10; ++i) grid.addGround(1.75, 0.25, i < 5 ? 0.f : 0.3f, 0.f);  // step
        grid.addObstacle(0.75, 0.75);  // a single stray point: below min_obstacle_points
        EXPECT_EQ(grid.endFrame(10.0 + frame, fusion), 3u);
    }
    EXPECT_FLOAT_EQ(grid.logodds(0), 2 * fusion.logodds_ground);  // per frame, not per point
    EXPECT_EQ(grid.state(0, fusion), travel::CellState::Traversable);
    EXPECT_NEAR(grid.groundHeight(0), 0.0098, 1e-3);
    EXPECT_NEAR(grid.slopeDeg(0), 2.0, 1e-4);
    EXPECT_EQ(grid.state(2, fusion), travel::CellState::Obstacle);
    EXPECT_EQ(grid.state(3, fusion), travel::CellState::Obstacle) << "0.3 m step";
    EXPECT_NEAR(grid.stepHeight(3), 0.3, 0.05);
    EXPECT_EQ(grid.state(5, fusion), travel::CellState::Unknown);
    EXPECT_DOUBLE_EQ(grid.lastSeen(0), 11.0);
}

// The step rule between cells (max_neighbour_step): a 0.15 m kerb is a step, a 10-degree
// ramp (whose heights differ by 0.044 m per 0.25 m cell, 0.18 m over 4 cells) is not, and a
// frame whose ground is tilted by 2 degrees (an attitude error) is levelled before fusion.
TEST(MapGrid, NeighbourStepSeparatesKerbFromRampAndLevelsTiltedFrames) {
    travel::GridFusionParams fusion;
    fusion.max_neighbour_step = 0.1f;
    const double r = 0.25;
    const auto fill = [&](travel::TraversabilityGrid& g, auto height, double tilt) {
        g.beginFrame();
        for (int iy = 0; iy < g.sizeY(); ++iy)
            for (int ix = 0; ix < g.sizeX(); ++ix)
                for (int k = 0; k < 3; ++k) {
                    const double x = g.cellCenterX(ix), y = g.cellCenterY(iy);
                    g.addGround(x, y, float(height(x) + tilt * x), 10.f);  // biased node slope
                }
        g.endFrame(1.0, fusion);
    };
    // Kerb along y at x = 1.1 (inside the cell column [1.0, 1.25)), 0.15 m; the TRAVEL nodes
    // at a kerb report ~10 degrees, which must not explain the step away.
    travel::TraversabilityGrid kerb;
    kerb.reset({0.0, 2.5, 0.0, 2.5, r});
    fill(
        kerb, [](double x) { return x < 1.1 ? 0.0 : 0.15; }, 0.0);
    const auto column = [&](const travel::TraversabilityGrid& g, int ix) {
        return g.state(g.cellIndex(ix, 5), fusion);
    };
    EXPECT_EQ(column(kerb, 4), travel::CellState::Obstacle) << "the kerb's cell";
    EXPECT_EQ(column(kerb, 1), travel::CellState::Traversable) << "road";
    EXPECT_EQ(column(kerb, 7), travel::CellState::Traversable) << "sidewalk";
    // A 10-degree ramp: nowhere a step.
    travel::TraversabilityGrid ramp;
    ramp.reset({0.0, 2.5, 0.0, 2.5, r});
    fill(
        ramp, [](double x) { return x * std::tan(10.0 * M_PI / 180.0); }, 0.0);
    std::size_t ramp_obstacles = 0;
    for (long c = 0; c < long(ramp.cellCount()); ++c)
        ramp_obstacles += ramp.state(c, fusion) == travel::CellState::Obstacle;
    EXPECT_EQ(ramp_obstacles, 0u);
    // Flat ground seen by a level frame, then by one tilted 2 degrees about y (0.087 m over the
    // 2.5 m grid): the second is levelled, the fused heights stay flat.
    travel::TraversabilityGrid flat;
    flat.reset({0.0, 2.5, 0.0, 2.5, r});
    fill(
        flat, [](double) { return 0.0; }, 0.0);
    fill(
        flat, [](double) { return 0.0; }, std::tan(2.0 * M_PI / 180.0));
    float lo = 1.f, hi = -1.f;
    for (long c = 0; c < long(flat.cellCount()); ++c)
        lo = std::min(lo, flat.groundHeight(c)), hi = std::max(hi, flat.groundHeight(c));
    EXPECT_LT(hi - lo, 0.005f) << "the tilted frame was not levelled";
}

std::string writeTemp(const std::string& name, const std::string& text) {
    const std::string path = tempPath() + "_" + name;
    std::ofstream(path) << text;
    return path;
}

std::string poseError(const std::string& text) {
    const std::string path = writeTemp("poses.txt", text);
    try {
        travel::readPoseFile(path);
    } catch (const std::exception& e) {
        std::remove(path.c_str());
        return e.what();
    }
    std::remove(path.c_str());
    return "";
}

TEST(PoseFiles, TumAndKittiAreReadAndInterpolated) {
    const std::string tum = writeTemp("tum.txt",
                                      "# t x y z qx qy qz qw\n"
                                      "1.0 0 0 0 0 0 0 1\n"
                                      "2.0 2 0 0 0 0 0.7071067811865476 0.7071067811865476\n");
    const auto t = travel::readPoseFile(tum);
    ASSERT_EQ(t.size(), 2u);
    ASSERT_TRUE(t.timed());
    const auto mid = travel::poseAt(t, 1.5);
    ASSERT_TRUE(mid);
    EXPECT_NEAR(mid->translation().x(), 1.0, 1e-9);
    EXPECT_NEAR(Eigen::AngleAxisd(mid->linear()).angle(), M_PI / 4, 1e-6);
    EXPECT_FALSE(travel::poseAt(t, 3.0));

    const std::string kitti = writeTemp("kitti.txt",
                                        "1 0 0 0 0 1 0 0 0 0 1 0\n"
                                        "1 0 0 0 0 1 0 0 0 0 1 1.5\n");
    const std::string calib = writeTemp("calib.txt",
                                        "P0: 1 0 0 0 0 1 0 0 0 0 1 0\n"
                                        "Tr: 0 -1 0 0 0 0 -1 0 1 0 0 0\n");
    auto k = travel::readPoseFile(kitti);
    ASSERT_EQ(k.size(), 2u);
    EXPECT_FALSE(k.timed());
    travel::kittiCameraToLidar(k, travel::readKittiCalibTr(calib));
    // Camera z forward = LiDAR x forward: 1.5 m along camera z is 1.5 m along LiDAR x.
    EXPECT_NEAR(k.poses[1].translation().x(), 1.5, 1e-9);
    EXPECT_NEAR(k.poses[1].translation().norm(), 1.5, 1e-9);
    for (const auto& p : {tum, kitti, calib}) std::remove(p.c_str());
}

TEST(PoseFiles, SequencePosesAndKittiLinesRoundTrip) {
    namespace fs = std::filesystem;
    const fs::path dir = tempPath() + "_sequence";
    fs::create_directories(dir);
    EXPECT_FALSE(travel::readSequenceLidarPoses(dir.string()));  // no poses.txt
    EXPECT_FALSE(travel::readSequenceLidarPoses(""));
    std::ofstream(dir / "poses.txt") << "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 0 0 1 0 0 0 0 1 1.5\n";
    auto uncalibrated = travel::readSequenceLidarPoses(dir.string());
    ASSERT_TRUE(uncalibrated);
    EXPECT_NEAR(uncalibrated->poses[1].translation().z(), 1.5, 1e-12);  // taken as LiDAR poses
    std::ofstream(dir / "calib.txt") << "Tr: 0 -1 0 0 0 0 -1 0 1 0 0 0\n";
    const auto lidar = travel::readSequenceLidarPoses(dir.string());
    ASSERT_TRUE(lidar);
    EXPECT_NEAR(lidar->poses[1].translation().x(), 1.5, 1e-9);  // camera z = LiDAR x
    // kittiPoseLine: 12 numbers that read back to the same pose.
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).matrix();
    pose.translation() = Eigen::Vector3d(1.25, -3.5, 0.125);
    const std::string file = writeTemp("line.txt", travel::kittiPoseLine(pose));
    const auto back = travel::readKittiPoses(file);
    ASSERT_EQ(back.size(), 1u);
    EXPECT_TRUE(back.poses[0].isApprox(pose, 1e-8));
    std::remove(file.c_str());
    fs::remove_all(dir);
}

TEST(PoseFiles, ErrorsNameTheFileLineAndWhatWasExpected) {
    EXPECT_NE(poseError("1 0 0 0 0 0 0 1\n2 0 0 0 0 0 1\n").find(":2: expected 8 numbers"),
              std::string::npos);
    EXPECT_NE(poseError("1 0 0 0 0 0 0 1\n2 0 x 0 0 0 0 1\n").find(":2: column 3: 'x'"),
              std::string::npos);
    EXPECT_NE(poseError("2 0 0 0 0 0 0 1\n1 0 0 0 0 0 0 1\n").find(":2: timestamp"),
              std::string::npos);
    EXPECT_NE(poseError("1 2 3\n").find(":1: expected 8 numbers (TUM"), std::string::npos);
    // A binary file (a scan given as poses) is named, not parsed and echoed.
    EXPECT_NE(poseError(std::string("\x3F\x80\0\0 1 2 3\n", 10))
                  .find(": not a text file (byte 0x80 at offset 1)"),
              std::string::npos);
    EXPECT_NE(poseError("").find("no poses"), std::string::npos);
    EXPECT_NE(poseError("1 0 0 0 0 0 0 5\n").find("unit length"), std::string::npos);
    const std::string calib = writeTemp("calib_bad.txt", "P0: 1 2 3\n");
    EXPECT_ANY_THROW(travel::readKittiCalibTr(calib));
    std::remove(calib.c_str());
    EXPECT_ANY_THROW(travel::readPoseFile("/nonexistent/poses.txt"));
}

TEST(TravelObstacles, HeightsAreAboveTheLocalGroundInTheLevelledRobotFrame) {
    // 4 x 4 cells of 2 m around the sensor, every node traversable ground at z = -1 (aligned
    // frame); the sensor 1 m above the robot origin.
    travel::Result result;
    travel::TerrainModel& t = result.terrain;
    t.resolution = 2.f, t.cells_per_side = 4, t.origin_xy = -4.f;
    t.nodes.assign(static_cast<std::size_t>(t.numNodes()), travel::TriNode{});
    for (travel::TriNode& n : t.nodes) {
        n.node_class = travel::NodeClass::Terrain;
        n.traversable = true;
        n.count = 10;
        n.refit_d = n.d = 1.f;  // z = -1
    }
    travel::AlignedCloud aligned;
    const auto add = [&](float x, float y, float z, travel::PointClass c) {
        aligned.x.push_back(x), aligned.y.push_back(y), aligned.z.push_back(z);
        aligned.valid.push_back(1);
        result.labels.push_back(c);
    };
    add(1.5f, 1.f, -0.5f, travel::PointClass::NonGround);  // 0.5 m above ground: obstacle
    add(1.5f, 1.f, -0.9f, travel::PointClass::NonGround);  // 0.1 m: the robot climbs it
    add(0.5f, 0.5f, -1.f, travel::PointClass::Ground);     // ground without a step
    add(5.f, 0.f, -0.5f, travel::PointClass::NonGround);   // outside: over the base plane
    add(1.f, 1.f, 2.5f, travel::PointClass::NonGround);    // 3.5 m: above max_height
    const Eigen::Isometry3f mount(Eigen::Translation3f(0.f, 0.f, 1.f));
    travel::TravelObstacles obstacles;
    travel::ObstaclePointCloud out;
    obstacles.compute(result, aligned, mount, out);
    ASSERT_EQ(out.size(), 2u);
    EXPECT_FLOAT_EQ(out.x[0], 1.5f);
    EXPECT_FLOAT_EQ(out.y[0], 1.f);
    EXPECT_FLOAT_EQ(out.z[0], 0.5f);
    EXPECT_FLOAT_EQ(out.x[1], 5.f);
    EXPECT_FLOAT_EQ(out.z[1], 0.5f);

    result.labels.pop_back();
    EXPECT_THROW(obstacles.compute(result, aligned, mount, out), std::invalid_argument);
    travel::NavSection bad;
    bad.max_height = -1;
    EXPECT_THROW(obstacles.setOptions(bad), travel::ConfigError);
}

}  // namespace
