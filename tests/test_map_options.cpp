// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The map's .ini keys (TraversabilityMapOptions), in-process CMultiMetricMap creation, the grid
// on its own, and the pose files (TUM, KITTI, calib.txt) with their error messages.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/system/filesystem.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "map/MapTestScene.hpp"
#include "travel/ConfigIO.hpp"
#include "travel_mrpt/CTraversabilityMap.hpp"
#include "travel_mrpt/PoseFiles.hpp"

namespace {

using travel_mrpt::TraversabilityMapOptions;

std::string errorOf(const std::string& ini_text, const std::string& section) {
    try {
        mrpt::config::CConfigFileMemory ini(ini_text);
        TraversabilityMapOptions o;
        o.loadFromConfigFile(ini, section);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

TEST(MapOptions, KeysOfMapFilterAndLibtravelAreRead) {
    mrpt::config::CConfigFileMemory ini(
        "[m]\nresolution=0.5\nmin_x=-5\nray_stride=3\nmax_step_height=0.2\npreset=vlp16\n"
        "sensor_height=1.1\nsensor_label=VLP.*\n");
    TraversabilityMapOptions o;
    o.loadFromConfigFile(ini, "m");
    EXPECT_EQ(o.geometry().resolution, 0.5);
    EXPECT_EQ(o.geometry().min_x, -5.0);
    EXPECT_EQ(o.ray_stride, 3);
    EXPECT_FLOAT_EQ(o.fusion().max_step_height, 0.2f);
    EXPECT_EQ(o.travel.params.sensor_height, 1.1);
    EXPECT_EQ(o.travel.params.num_rings, 16) << "from the vlp16 preset";
    EXPECT_EQ(o.travel.sensor_label, "VLP.*");

    // Saved text reads back to the same values.
    mrpt::config::CConfigFileMemory saved;
    o.saveToConfigFile(saved, "s");
    mrpt::config::CConfigFileMemory reread(saved.getContent());
    TraversabilityMapOptions back;
    back.loadFromConfigFile(reread, "s");
    EXPECT_EQ(back.geometry().min_x, -5.0);
    EXPECT_EQ(back.ray_stride, 3);
    EXPECT_EQ(back.travel.params.sensor_height, 1.1);
}

TEST(MapOptions, BadKeysAreRejectedWithTheirName) {
    EXPECT_NE(errorOf("[m]\nresolutoin=0.5\n", "m").find("unknown key 'resolutoin'"),
              std::string::npos);
    EXPECT_NE(errorOf("[m]\nresolutoin=0.5\n", "m").find("[m]"), std::string::npos);
    EXPECT_NE(errorOf("[m]\nresolutoin=0.5\n", "m").find("did you mean 'resolution'"),
              std::string::npos);
    // The map's slope limit has its own name: the old one is libtravel's.
    EXPECT_NE(errorOf("[m]\nmax_traversable_slope_dg=20\n", "m").find("max_traversable_slope_deg"),
              std::string::npos);
    EXPECT_NE(errorOf("[m]\nresolution=abc\n", "m")
                  .find("invalid value for 'resolution': 'abc' is not a finite number"),
              std::string::npos);
    EXPECT_NE(errorOf("[m]\nray_stride=1.5\n", "m").find("'1.5' is not an integer"),
              std::string::npos);
    EXPECT_NE(errorOf("[m]\nmin_x=5\nmax_x=1\n", "m").find("min_x"), std::string::npos);
    EXPECT_NE(errorOf("[m]\nsensor_height=-1\n", "m").find("sensor_height"), std::string::npos);
    EXPECT_NE(errorOf("[m]\nresolution=0.0001\nmin_x=-100\nmax_x=100\n", "m").find("16384"),
              std::string::npos);
}

TEST(MapOptions, IniFileErrorsNameFileLineAndSection) {
    const std::string path = mrpt::system::getTempFileName() + "_map_options.ini";
    std::ofstream(path) << "[other]\nresolution=1\n[m]\nresolution=0.5\n  ray_strid=3\n";
    std::string message;
    try {
        mrpt::config::CConfigFile ini(path);
        TraversabilityMapOptions o;
        o.loadFromConfigFile(ini, "m");
    } catch (const std::exception& e) {
        message = e.what();
    }
    std::remove(path.c_str());
    EXPECT_NE(message.find(path + ":5:3: section [m]: unknown key 'ray_strid'"), std::string::npos)
        << message;
    EXPECT_NE(message.find("did you mean 'ray_stride'"), std::string::npos) << message;
}

TEST(MapOptions, SameKeysAsTheMapSectionOfAConfigFile) {
    // A [map] section of the one configuration file gives the same options as the flat section.
    travel::Config config;
    travel::applyConfigText("[map]\nresolution = 0.5\nmax_traversable_slope_deg = 12\n", "c.ini",
                            config);
    mrpt::config::CConfigFileMemory ini("[m]\nresolution=0.5\nmax_traversable_slope_deg=12\n");
    TraversabilityMapOptions o;
    o.loadFromConfigFile(ini, "m");
    EXPECT_EQ(o.resolution, config.map.resolution);
    EXPECT_EQ(o.fusion().max_slope_deg, config.map.max_traversable_slope_deg);
    EXPECT_EQ(o.travel.params.max_slope_deg, travel::Params().max_slope_deg)
        << "travel's untouched";
}

TEST(MapOptions, CMultiMetricMapCreatesTheMapFromAnIni) {
    mrpt::config::CConfigFileMemory ini(travel_map_test::mapIni("MAP"));
    mrpt::maps::TSetOfMetricMapInitializers initializers;
    initializers.loadFromConfigFile(ini, "MAP");
    mrpt::maps::CMultiMetricMap maps(initializers);
    auto map = maps.mapByClass<travel_mrpt::CTraversabilityMap>();
    ASSERT_TRUE(map);
    EXPECT_EQ(map->grid().sizeX(), 112);  // 28 m / 0.25 m
    EXPECT_EQ(map->grid().sizeY(), 88);   // 22 m / 0.25 m
    EXPECT_EQ(map->options().travel.params.sensor_height, 1.8);
    // max_traversable_slope_deg (the map's) and max_slope_deg (libtravel's) are distinct keys:
    // value (20 in the .ini, libtravel's default 25) survives.
    mrpt::config::CConfigFileMemory saved;
    map->options().saveToConfigFile(saved, "m");
    travel_mrpt::TraversabilityMapOptions reread;
    reread.loadFromConfigFile(saved, "m");
    EXPECT_FLOAT_EQ(reread.fusion().max_slope_deg, 20.f);
    EXPECT_FLOAT_EQ(reread.fusion().max_neighbour_step, 0.1f);

    // An unknown key in the .ini fails the creation with the key and section named.
    mrpt::config::CConfigFileMemory bad(travel_map_test::mapIni("MAP") + "colour=red\n");
    mrpt::maps::TSetOfMetricMapInitializers bad_initializers;
    try {
        bad_initializers.loadFromConfigFile(bad, "MAP");
        FAIL() << "no error for an unknown key";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("colour"), std::string::npos) << e.what();
    }
}

TEST(TraversabilityGrid, OneUpdatePerCellAndFrame) {
    travel_mrpt::TraversabilityGrid grid;
    grid.reset({0.0, 2.0, 0.0, 1.0, 0.5});
    travel_mrpt::GridFusionParams fusion;
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
    EXPECT_EQ(grid.state(0, fusion), travel_mrpt::CellState::Traversable);
    EXPECT_NEAR(grid.groundHeight(0), 0.0098, 1e-3);
    EXPECT_NEAR(grid.slopeDeg(0), 2.0, 1e-4);
    EXPECT_EQ(grid.state(2, fusion), travel_mrpt::CellState::Obstacle);
    EXPECT_EQ(grid.state(3, fusion), travel_mrpt::CellState::Obstacle) << "0.3 m step";
    EXPECT_NEAR(grid.stepHeight(3), 0.3, 0.05);
    EXPECT_EQ(grid.state(5, fusion), travel_mrpt::CellState::Unknown);
    EXPECT_DOUBLE_EQ(grid.lastSeen(0), 11.0);
}

// The step rule between cells (max_neighbour_step): a 0.15 m kerb is a step, a 10-degree
// ramp (whose heights differ by 0.044 m per 0.25 m cell, 0.18 m over 4 cells) is not, and a
// frame whose ground is tilted by 2 degrees (an attitude error) is levelled before fusion.
TEST(MapGrid, NeighbourStepSeparatesKerbFromRampAndLevelsTiltedFrames) {
    travel_mrpt::GridFusionParams fusion;
    fusion.max_neighbour_step = 0.1f;
    const double r = 0.25;
    const auto fill = [&](travel_mrpt::TraversabilityGrid& g, auto height, double tilt) {
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
    travel_mrpt::TraversabilityGrid kerb;
    kerb.reset({0.0, 2.5, 0.0, 2.5, r});
    fill(
        kerb, [](double x) { return x < 1.1 ? 0.0 : 0.15; }, 0.0);
    const auto column = [&](const travel_mrpt::TraversabilityGrid& g, int ix) {
        return g.state(g.cellIndex(ix, 5), fusion);
    };
    EXPECT_EQ(column(kerb, 4), travel_mrpt::CellState::Obstacle) << "the kerb's cell";
    EXPECT_EQ(column(kerb, 1), travel_mrpt::CellState::Traversable) << "road";
    EXPECT_EQ(column(kerb, 7), travel_mrpt::CellState::Traversable) << "sidewalk";
    // A 10-degree ramp: nowhere a step.
    travel_mrpt::TraversabilityGrid ramp;
    ramp.reset({0.0, 2.5, 0.0, 2.5, r});
    fill(
        ramp, [](double x) { return x * std::tan(10.0 * M_PI / 180.0); }, 0.0);
    std::size_t ramp_obstacles = 0;
    for (long c = 0; c < long(ramp.cellCount()); ++c)
        ramp_obstacles += ramp.state(c, fusion) == travel_mrpt::CellState::Obstacle;
    EXPECT_EQ(ramp_obstacles, 0u);
    // Flat ground seen by a level frame, then by one tilted 2 degrees about y (0.087 m over the
    // 2.5 m grid): the second is levelled, the fused heights stay flat.
    travel_mrpt::TraversabilityGrid flat;
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
    const std::string path = mrpt::system::getTempFileName() + "_" + name;
    std::ofstream(path) << text;
    return path;
}

std::string poseError(const std::string& text) {
    const std::string path = writeTemp("poses.txt", text);
    try {
        travel_mrpt::readPoseFile(path);
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
    const auto t = travel_mrpt::readPoseFile(tum);
    ASSERT_EQ(t.size(), 2u);
    ASSERT_TRUE(t.timed());
    const auto mid = travel_mrpt::poseAt(t, 1.5);
    ASSERT_TRUE(mid);
    EXPECT_NEAR(mid->translation().x(), 1.0, 1e-9);
    EXPECT_NEAR(Eigen::AngleAxisd(mid->linear()).angle(), M_PI / 4, 1e-6);
    EXPECT_FALSE(travel_mrpt::poseAt(t, 3.0));

    const std::string kitti = writeTemp("kitti.txt",
                                        "1 0 0 0 0 1 0 0 0 0 1 0\n"
                                        "1 0 0 0 0 1 0 0 0 0 1 1.5\n");
    const std::string calib = writeTemp("calib.txt",
                                        "P0: 1 0 0 0 0 1 0 0 0 0 1 0\n"
                                        "Tr: 0 -1 0 0 0 0 -1 0 1 0 0 0\n");
    auto k = travel_mrpt::readPoseFile(kitti);
    ASSERT_EQ(k.size(), 2u);
    EXPECT_FALSE(k.timed());
    travel_mrpt::kittiCameraToLidar(k, travel_mrpt::readKittiCalibTr(calib));
    // Camera z forward = LiDAR x forward: 1.5 m along camera z is 1.5 m along LiDAR x.
    EXPECT_NEAR(k.poses[1].translation().x(), 1.5, 1e-9);
    EXPECT_NEAR(k.poses[1].translation().norm(), 1.5, 1e-9);
    for (const auto& p : {tum, kitti, calib}) std::remove(p.c_str());
}

TEST(PoseFiles, ErrorsNameTheFileLineAndWhatWasExpected) {
    EXPECT_NE(poseError("1 0 0 0 0 0 0 1\n2 0 0 0 0 0 1\n").find(":2: expected 8 numbers"),
              std::string::npos);
    EXPECT_NE(poseError("1 0 0 0 0 0 0 1\n2 0 x 0 0 0 0 1\n").find(":2: column 3: 'x'"),
              std::string::npos);
    EXPECT_NE(poseError("2 0 0 0 0 0 0 1\n1 0 0 0 0 0 0 1\n").find(":2: timestamp"),
              std::string::npos);
    EXPECT_NE(poseError("1 2 3\n").find(":1: expected 8 numbers (TUM"), std::string::npos);
    EXPECT_NE(poseError("").find("no poses"), std::string::npos);
    EXPECT_NE(poseError("1 0 0 0 0 0 0 5\n").find("unit length"), std::string::npos);
    const std::string calib = writeTemp("calib_bad.txt", "P0: 1 2 3\n");
    EXPECT_ANY_THROW(travel_mrpt::readKittiCalibTr(calib));
    std::remove(calib.c_str());
    EXPECT_ANY_THROW(travel_mrpt::readPoseFile("/nonexistent/poses.txt"));
}

}  // namespace
