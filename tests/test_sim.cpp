// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The synthetic LiDAR: geometry of the returns, ground truth, ordering and reproducibility.
#include "travel/sim/Scene.hpp"
#include "travel/sim/Scenes.hpp"
#include "travel/sim/SyntheticLidar.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <set>
#include <stdexcept>
#include <vector>

namespace {

using travel::sim::GtClass;
using travel::sim::LidarModel;
using travel::sim::PointOrder;
using travel::sim::Scan;
using travel::sim::scan;
using travel::sim::Scene;
using travel::sim::sensorPoseAt;

constexpr double kPi = 3.14159265358979323846;
constexpr double kH = travel::sim::kSensorHeight;
constexpr double kInfinity = travel::sim::kInfinity;

Eigen::Vector3d sensorPoint(const Scan& s, std::size_t i) {
    return {s.cloud.x[i], s.cloud.y[i], s.cloud.z[i]};
}

Eigen::Isometry3d levelPose(const Scene& scene) {
    return sensorPoseAt(scene, 0.0, 0.0, kH, 0.0, 0.0, 0.0);
}

int columnOf(const Scan& s, std::size_t i, const LidarModel& model) {
    return static_cast<int>(std::lround(s.cloud.time[i] / model.sweep_period * model.columns));
}

void expectConsistentSizes(const Scan& s) {
    const std::size_t n = s.cloud.size();
    EXPECT_TRUE(s.cloud.hasRing());
    EXPECT_TRUE(s.cloud.hasTime());
    EXPECT_EQ(s.cloud.intensity.size(), n);
    EXPECT_EQ(s.gt.cls.size(), n);
    EXPECT_EQ(s.gt.instance.size(), n);
    EXPECT_EQ(s.gt.height_above_ground.size(), n);
}

TEST(Sim, ModelFactories) {
    const LidarModel hdl64 = LidarModel::hdl64();
    EXPECT_EQ(hdl64.numBeams(), 64u);
    EXPECT_EQ(hdl64.columns, 2083);
    const std::vector<double> rings = hdl64.elevationsByRing();
    EXPECT_NEAR(rings.front(), -24.33, 1e-9);
    EXPECT_NEAR(rings.back(), 2.0, 1e-9);
    EXPECT_TRUE(std::is_sorted(rings.begin(), rings.end()));
    // The lower block is sparser than the upper one.
    EXPECT_GT(rings[1] - rings[0], rings[63] - rings[62]);

    EXPECT_EQ(LidarModel::hdl32().numBeams(), 32u);
    EXPECT_EQ(LidarModel::hdl32().columns, 1084);
    EXPECT_EQ(LidarModel::vlp16().numBeams(), 16u);
    EXPECT_EQ(LidarModel::os128().numBeams(), 128u);
    EXPECT_EQ(LidarModel::os128().columns, 1024);
    EXPECT_EQ(LidarModel::hdl64(500).columns, 500);

    const LidarModel vlp16 = LidarModel::vlp16();
    for (std::size_t ring = 0; ring < 16; ++ring) {
        EXPECT_NEAR(vlp16.elevationsByRing()[ring], -15.0 + 2.0 * static_cast<double>(ring), 1e-9);
    }

    LidarModel bad = LidarModel::vlp16();
    bad.columns = 0;
    EXPECT_THROW(bad.validate(), std::invalid_argument);
    EXPECT_THROW(scan(travel::sim::flatGround(), bad, Eigen::Isometry3d::Identity()),
                 std::invalid_argument);
}

TEST(Sim, TerrainFeatures) {
    const Scene ramp = travel::sim::slope(20.0);
    const double tan20 = std::tan(20.0 * kPi / 180.0);
    EXPECT_DOUBLE_EQ(ramp.terrainHeight(0.0, 0.0), 0.0);
    EXPECT_NEAR(ramp.terrainHeight(11.0, 3.0), 5.0 * tan20, 1e-12);
    EXPECT_NEAR(ramp.terrainHeight(40.0, 3.0), 15.0 * tan20, 1e-12);  // plateau
    EXPECT_DOUBLE_EQ(ramp.terrainHeight(11.0, 12.0), 0.0);            // beside the ramp
    EXPECT_NEAR(ramp.terrainSlopeDeg(11.0, 3.0), 20.0, 1e-9);
    EXPECT_NEAR(ramp.terrainSlopeDeg(40.0, 3.0), 0.0, 1e-12);

    const Scene kerbs = travel::sim::kerbsAndSteps();
    EXPECT_DOUBLE_EQ(kerbs.terrainHeight(0.0, 0.0), 0.0);
    EXPECT_DOUBLE_EQ(kerbs.terrainHeight(0.0, 5.0), 0.15);
    EXPECT_DOUBLE_EQ(kerbs.terrainHeight(0.0, -6.0), 0.15);
    EXPECT_DOUBLE_EQ(kerbs.terrainHeight(8.2, 0.0), 0.15);
    EXPECT_DOUBLE_EQ(kerbs.terrainHeight(8.6, 0.0), 0.30);
    EXPECT_DOUBLE_EQ(kerbs.terrainHeight(20.0, 0.0), 0.45);

    // The analytic gradient of bumps and roughness matches central differences.
    const Scene bumpy = travel::sim::bumpyTerrain();
    for (const Eigen::Vector2d& p : {Eigen::Vector2d(8.0, 4.0), Eigen::Vector2d(-5.3, 10.1)}) {
        const double e = 1e-6;
        const Eigen::Vector2d numeric(
            (bumpy.terrainHeight(p.x() + e, p.y()) - bumpy.terrainHeight(p.x() - e, p.y())) /
                (2 * e),
            (bumpy.terrainHeight(p.x(), p.y() + e) - bumpy.terrainHeight(p.x(), p.y() - e)) /
                (2 * e));
        EXPECT_NEAR((bumpy.terrainGradient(p.x(), p.y()) - numeric).norm(), 0.0, 1e-6);
    }

    // Region bounds are never below the true height.
    for (const Scene& scene : {ramp, kerbs, bumpy, travel::sim::mixed()}) {
        for (double x = -30.0; x < 30.0; x += 1.7) {
            for (double y = -30.0; y < 30.0; y += 1.3) {
                const Eigen::Vector2d lo(x, y), hi(x + 1.0, y + 1.0);
                const double bound = scene.terrainUpperBound(lo, hi);
                EXPECT_LE(bound, scene.terrainUpperBound() + 1e-12);
                for (double fx : {0.0, 0.3, 0.7, 1.0}) {
                    for (double fy : {0.0, 0.5, 1.0}) {
                        EXPECT_LE(scene.terrainHeight(x + fx, y + fy), bound + 1e-12);
                    }
                }
            }
        }
    }
}

TEST(Sim, FlatGroundLevelVlp16) {
    const Scene scene = travel::sim::flatGround();
    const LidarModel model = LidarModel::vlp16();
    const Scan s = scan(scene, model, levelPose(scene));
    expectConsistentSizes(s);
    // The 8 downward beams (-15..-1 deg) all reach the ground within 100 m; the rest see sky.
    ASSERT_EQ(s.cloud.size(), 8u * 1800u);
    for (std::size_t i = 0; i < s.cloud.size(); ++i) {
        EXPECT_LT(std::abs(s.cloud.z[i] + kH), 1e-3);
        EXPECT_EQ(s.gt.cls[i], GtClass::Ground);
        EXPECT_EQ(s.gt.instance[i], 0u);
        EXPECT_LT(std::abs(s.gt.height_above_ground[i]), 1e-3);
        EXPECT_LT(s.cloud.ring[i], 8u);
    }
}

TEST(Sim, RingsAndTimes) {
    const Scene scene = travel::sim::flatGround();
    LidarModel model = LidarModel::vlp16(360);
    // Beam table in a scrambled order: the ring is still the elevation rank.
    std::reverse(model.elevations_deg.begin(), model.elevations_deg.end());
    std::swap(model.elevations_deg[3], model.elevations_deg[11]);
    model.emit_no_returns = true;
    model.max_range = 1000.0;  // every downward beam hits
    const Scan s = scan(scene, model, levelPose(scene));
    expectConsistentSizes(s);
    ASSERT_EQ(s.cloud.size(), 16u * 360u);

    std::set<int> rings(s.cloud.ring.begin(), s.cloud.ring.end());
    EXPECT_EQ(rings.size(), 16u);
    EXPECT_EQ(*rings.begin(), 0);
    EXPECT_EQ(*rings.rbegin(), 15);

    for (std::size_t i = 0; i < s.cloud.size(); ++i) {
        // Ring-major: ring r holds points r * columns .. (r + 1) * columns - 1, column ascending.
        const int ring = static_cast<int>(i / 360), column = static_cast<int>(i % 360);
        EXPECT_EQ(s.cloud.ring[i], ring);
        EXPECT_EQ(columnOf(s, i, model), column);
        EXPECT_GE(s.cloud.time[i], 0.f);
        EXPECT_LT(s.cloud.time[i], static_cast<float>(model.sweep_period));
        if (column > 0) {
            EXPECT_GT(s.cloud.time[i], s.cloud.time[i - 1]);
        }
        if (s.gt.cls[i] == GtClass::NoReturn) {
            EXPECT_GE(ring, 8);  // only upward beams miss
            continue;
        }
        const Eigen::Vector3d p = sensorPoint(s, i);
        const double elevation_deg = std::atan2(p.z(), p.head<2>().norm()) * 180.0 / kPi;
        EXPECT_NEAR(elevation_deg, -15.0 + 2.0 * ring, 1e-3);
        // Azimuth 0 = +x, counter-clockwise.
        const double azimuth = std::atan2(p.y(), p.x());
        const double expected = 2.0 * kPi * column / 360.0;
        EXPECT_NEAR(std::remainder(azimuth - expected, 2.0 * kPi), 0.0, 1e-5);
    }
}

TEST(Sim, ColumnMajorOrder) {
    const Scene scene = travel::sim::flatGround();
    LidarModel model = LidarModel::hdl32(200);
    model.order = PointOrder::ColumnMajor;
    model.emit_no_returns = true;
    const Scan s = scan(scene, model, levelPose(scene));
    ASSERT_EQ(s.cloud.size(), 32u * 200u);
    for (std::size_t i = 0; i < s.cloud.size(); ++i) {
        EXPECT_EQ(s.cloud.ring[i], i % 32);
        EXPECT_EQ(columnOf(s, i, model), static_cast<int>(i / 32));
        if (i > 0) {
            EXPECT_GE(s.cloud.time[i], s.cloud.time[i - 1]);
        }
    }
}

TEST(Sim, ObjectsAreNonGroundWithTheirInstance) {
    const Scene scene = travel::sim::urbanObjects();
    const LidarModel model = LidarModel::hdl64(1000);
    const Eigen::Isometry3d pose = levelPose(scene);
    const Scan s = scan(scene, model, pose);
    expectConsistentSizes(s);

    std::set<uint32_t> seen;
    for (std::size_t i = 0; i < s.cloud.size(); ++i) {
        const uint32_t id = s.gt.instance[i];
        if (id == 0) {
            EXPECT_EQ(s.gt.cls[i], GtClass::Ground);  // urbanObjects has flat terrain only
            continue;
        }
        seen.insert(id);
        EXPECT_EQ(s.gt.cls[i], GtClass::NonGround);
        EXPECT_EQ(s.cloud.intensity[i], 0.8f);
        const Eigen::Vector3d world = pose * sensorPoint(s, i);
        EXPECT_NEAR(s.gt.height_above_ground[i], world.z(), 1e-3);
        for (const travel::sim::Pole& pole : scene.poles) {
            if (pole.id != id) continue;
            // On the mantle or on the top cap.
            const double axis_distance = (world.head<2>() - pole.centre).norm();
            EXPECT_LE(axis_distance, pole.radius + 1e-4);
            EXPECT_TRUE(std::abs(axis_distance - pole.radius) < 1e-4 ||
                        std::abs(world.z() - pole.height) < 1e-4);
            EXPECT_LE(world.z(), pole.height + 1e-4);
        }
        if (id <= 3) {
            EXPECT_LE(world.z(), 1.5 + 1e-4);  // cars
        }
    }
    EXPECT_EQ(seen, (std::set<uint32_t>{1, 2, 3, 4, 5, 6, 7, 8}));
}

TEST(Sim, PoleOccludesWallBehindIt) {
    const Scene scene = travel::sim::urbanObjects();
    const LidarModel model = LidarModel::hdl64(2083);
    const Scan s = scan(scene, model, levelPose(scene));
    // The 3 m wall (id 8) is at x = 24; pole 6 at (12, -6) shadows it around y = -12.
    int wall_hits_in_shadow = 0, pole_hits = 0;
    for (std::size_t i = 0; i < s.cloud.size(); ++i) {
        const double azimuth = std::atan2(s.cloud.y[i], s.cloud.x[i]);
        const double pole_azimuth = std::atan2(-6.0, 12.0);
        if (std::abs(azimuth - pole_azimuth) > 0.4 * 0.12 / std::hypot(12.0, 6.0)) continue;
        if (s.cloud.z[i] > 0.0) continue;  // below the sensor height: the pole covers all of it
        if (s.gt.instance[i] == 8) ++wall_hits_in_shadow;
        if (s.gt.instance[i] == 6) ++pole_hits;
    }
    EXPECT_GT(pole_hits, 0);
    EXPECT_EQ(wall_hits_in_shadow, 0);
}

// Counts the terrain hits on the inclined part of a ramp by class.
void countRampClasses(double slope_deg, int& ground, int& non_ground) {
    const Scene scene = travel::sim::slope(slope_deg);
    const Eigen::Isometry3d pose = levelPose(scene);
    const Scan s = scan(scene, LidarModel::hdl64(720), pose);
    ground = non_ground = 0;
    for (std::size_t i = 0; i < s.cloud.size(); ++i) {
        const Eigen::Vector3d world = pose * sensorPoint(s, i);
        if (world.x() < 6.5 || world.x() > 20.5 || std::abs(world.y()) > 9.5) continue;
        ASSERT_EQ(s.gt.instance[i], 0u);
        EXPECT_NEAR(world.z(), scene.terrainHeight(world.x(), world.y()), 1e-3);
        (s.gt.cls[i] == GtClass::Ground ? ground : non_ground)++;
    }
}

TEST(Sim, SteepRampIsNonGround) {
    int ground = 0, non_ground = 0;
    countRampClasses(30.0, ground, non_ground);
    EXPECT_GT(non_ground, 100);
    EXPECT_EQ(ground, 0);
    countRampClasses(20.0, ground, non_ground);
    EXPECT_GT(ground, 100);
    EXPECT_EQ(non_ground, 0);
    countRampClasses(10.0, ground, non_ground);
    EXPECT_GT(ground, 100);
    EXPECT_EQ(non_ground, 0);

    // The plateau above a steep ramp is flat again: Ground. Seen from a sensor standing on it.
    const Scene scene = travel::sim::slope(30.0);
    const Eigen::Isometry3d pose = sensorPoseAt(scene, 35.0, 0.0, kH, 0.0, 0.0, 0.0);
    const Scan s = scan(scene, LidarModel::hdl64(720), pose);
    const double plateau_height = 15.0 * std::tan(30.0 * kPi / 180.0);
    int plateau = 0;
    for (std::size_t i = 0; i < s.cloud.size(); ++i) {
        const Eigen::Vector3d world = pose * sensorPoint(s, i);
        if (world.x() < 21.5 || std::abs(world.y()) > 9.5) continue;
        EXPECT_NEAR(world.z(), plateau_height, 1e-3);
        EXPECT_EQ(s.gt.cls[i], GtClass::Ground);
        ++plateau;
    }
    EXPECT_GT(plateau, 1000);
}

TEST(Sim, KerbAndStairFacesAreGround) {
    const Scene scene = travel::sim::kerbsAndSteps();
    const Eigen::Isometry3d pose = levelPose(scene);
    const Scan s = scan(scene, LidarModel::hdl64(), pose);
    int kerb_face = 0, riser = 0;
    for (std::size_t i = 0; i < s.cloud.size(); ++i) {
        const Eigen::Vector3d world = pose * sensorPoint(s, i);
        const bool on_kerb_face = std::abs(world.y() - 4.5) < 1e-4 && world.x() < 7.9 &&
                                  world.z() > 1e-3 && world.z() < 0.149;
        const bool on_first_riser = std::abs(world.x() - 8.0) < 1e-4 &&
                                    std::abs(world.y() + 0.5) < 4.9 && world.z() > 1e-3 &&
                                    world.z() < 0.149;
        if (!on_kerb_face && !on_first_riser) continue;
        (on_kerb_face ? kerb_face : riser)++;
        EXPECT_EQ(s.gt.cls[i], GtClass::Ground);
        EXPECT_EQ(s.gt.instance[i], 0u);
        // Face hits are measured from the foot of the face.
        EXPECT_NEAR(s.gt.height_above_ground[i], world.z(), 1e-4);
    }
    EXPECT_GT(kerb_face, 0);
    EXPECT_GT(riser, 0);
}

TEST(Sim, TiltedPoseGivesTheSameWorld) {
    for (const Scene& scene : {travel::sim::bumpyTerrain(), travel::sim::mixed()}) {
        const Eigen::Isometry3d pose = sensorPoseAt(scene, 2.0, -1.0, kH, 8.0, -6.0, 30.0);
        EXPECT_NEAR(pose.translation().z(), scene.terrainHeight(2.0, -1.0) + kH, 1e-12);
        const Scan s = scan(scene, LidarModel::hdl32(), pose);
        ASSERT_GT(s.cloud.size(), 10000u);
        int terrain = 0;
        for (std::size_t i = 0; i < s.cloud.size(); ++i) {
            if (s.gt.instance[i] != 0) continue;
            const Eigen::Vector3d world = pose * sensorPoint(s, i);
            // A face hit lies on the foot side of the face, but float rounding of the cloud may
            // move it across: compare with the terrain on both sides.
            double low = kInfinity, high = -kInfinity;
            for (const Eigen::Vector2d& offset :
                 {Eigen::Vector2d(0, 0), Eigen::Vector2d(1e-4, 0), Eigen::Vector2d(-1e-4, 0),
                  Eigen::Vector2d(0, 1e-4), Eigen::Vector2d(0, -1e-4)}) {
                const double h =
                    scene.terrainHeight(world.x() + offset.x(), world.y() + offset.y());
                low = std::min(low, h), high = std::max(high, h);
            }
            EXPECT_NEAR(world.z() - low, s.gt.height_above_ground[i], 1e-3);
            EXPECT_GT(world.z(), low - 1e-3);
            EXPECT_LT(world.z(), high + 1e-3);
            if (high - low < 1e-3) ++terrain;
        }
        EXPECT_GT(terrain, 10000);
    }
}

TEST(Sim, TiltedMountTiltsTheCloud) {
    // With roll and pitch the ground is no longer at a constant sensor-frame z, yet the points
    // mapped through the pose still lie on it.
    const Scene scene = travel::sim::flatGround();
    const Eigen::Isometry3d pose = sensorPoseAt(scene, 0.0, 0.0, kH, 8.0, -6.0, 0.0);
    const Scan s = scan(scene, LidarModel::vlp16(), pose);
    ASSERT_FALSE(s.cloud.empty());
    double min_z = 0.0, max_z = -1e9;
    for (std::size_t i = 0; i < s.cloud.size(); ++i) {
        const Eigen::Vector3d world = pose * sensorPoint(s, i);
        EXPECT_LT(std::abs(world.z()), 1e-3);
        min_z = std::min<double>(min_z, s.cloud.z[i]);
        max_z = std::max<double>(max_z, s.cloud.z[i]);
    }
    EXPECT_GT(max_z - min_z, 1.0);
}

TEST(Sim, SeededNoiseIsReproducible) {
    const Scene scene = travel::sim::mixed();
    LidarModel model = LidarModel::hdl32(400);
    model.range_noise_sigma = 0.02;
    model.seed = 7;
    const Eigen::Isometry3d pose = levelPose(scene);
    const Scan a = scan(scene, model, pose);
    const Scan b = scan(scene, model, pose);
    ASSERT_EQ(a.cloud.size(), b.cloud.size());
    EXPECT_EQ(a.cloud.x, b.cloud.x);
    EXPECT_EQ(a.cloud.y, b.cloud.y);
    EXPECT_EQ(a.cloud.z, b.cloud.z);
    EXPECT_EQ(a.cloud.intensity, b.cloud.intensity);
    EXPECT_EQ(a.cloud.ring, b.cloud.ring);
    EXPECT_EQ(a.cloud.time, b.cloud.time);
    EXPECT_EQ(a.gt.cls, b.gt.cls);
    EXPECT_EQ(a.gt.instance, b.gt.instance);
    EXPECT_EQ(a.gt.height_above_ground, b.gt.height_above_ground);

    model.seed = 8;
    const Scan c = scan(scene, model, pose);
    ASSERT_EQ(a.cloud.size(), c.cloud.size());  // noise never changes what was hit
    EXPECT_EQ(a.gt.cls, c.gt.cls);
    EXPECT_NE(a.cloud.x, c.cloud.x);

    // The noise is along the ray with about the requested sigma.
    model.range_noise_sigma = 0.0;
    const Scan clean = scan(scene, model, pose);
    ASSERT_EQ(clean.cloud.size(), a.cloud.size());
    double sum_sq = 0.0;
    for (std::size_t i = 0; i < a.cloud.size(); ++i) {
        const Eigen::Vector3d noisy = sensorPoint(a, i), exact = sensorPoint(clean, i);
        EXPECT_NEAR(noisy.normalized().dot(exact.normalized()), 1.0, 1e-6);
        sum_sq += std::pow(noisy.norm() - exact.norm(), 2);
    }
    EXPECT_NEAR(std::sqrt(sum_sq / static_cast<double>(a.cloud.size())), 0.02, 0.002);
}

TEST(Sim, NoReturns) {
    const Scene scene = travel::sim::urbanObjects();
    LidarModel model = LidarModel::vlp16(900);
    model.emit_no_returns = true;
    const Scan with = scan(scene, model, levelPose(scene));
    expectConsistentSizes(with);
    ASSERT_EQ(with.cloud.size(), 16u * 900u);
    std::size_t no_returns = 0;
    for (std::size_t i = 0; i < with.cloud.size(); ++i) {
        const bool at_origin =
            with.cloud.x[i] == 0.f && with.cloud.y[i] == 0.f && with.cloud.z[i] == 0.f;
        EXPECT_EQ(at_origin, with.gt.cls[i] == GtClass::NoReturn);
        if (!at_origin) continue;
        ++no_returns;
        EXPECT_EQ(with.gt.instance[i], 0u);
        EXPECT_TRUE(std::isnan(with.gt.height_above_ground[i]));
    }
    EXPECT_GT(no_returns, 5u * 900u);  // most upward beams see only sky

    model.emit_no_returns = false;
    const Scan without = scan(scene, model, levelPose(scene));
    EXPECT_EQ(without.cloud.size(), with.cloud.size() - no_returns);
    for (std::size_t i = 0; i < without.cloud.size(); ++i) {
        EXPECT_NE(without.gt.cls[i], GtClass::NoReturn);
        EXPECT_FALSE(without.cloud.x[i] == 0.f && without.cloud.y[i] == 0.f &&
                     without.cloud.z[i] == 0.f);
    }
}

TEST(Sim, RangeLimits) {
    const Scene scene = travel::sim::flatGround();
    LidarModel model = LidarModel::uniform(1, -30.0, -30.0, 90);
    model.min_range = 4.0;  // the beam hits at 1.73 / sin(30 deg) = 3.46 m
    EXPECT_TRUE(scan(scene, model, levelPose(scene)).cloud.empty());
    model.min_range = 3.0;
    EXPECT_EQ(scan(scene, model, levelPose(scene)).cloud.size(), 90u);
    model.max_range = 3.4;
    EXPECT_TRUE(scan(scene, model, levelPose(scene)).cloud.empty());
}

// The accelerated march finds the same first crossing as a plain fine march.
TEST(Sim, MarchMatchesBruteForce) {
    for (const Scene& scene :
         {travel::sim::bumpyTerrain(), travel::sim::kerbsAndSteps(), travel::sim::slope(20.0)}) {
        LidarModel model = LidarModel::uniform(24, -25.0, 3.0, 48);
        model.emit_no_returns = true;
        model.max_range = 60.0;
        const Eigen::Isometry3d pose = sensorPoseAt(scene, 1.0, 2.0, kH, 3.0, -2.0, 10.0);
        const Scan s = scan(scene, model, pose);
        ASSERT_EQ(s.cloud.size(), 24u * 48u);
        const std::vector<double> elevations = model.elevationsByRing();
        int disagreements = 0;
        for (std::size_t i = 0; i < s.cloud.size(); ++i) {
            const double elevation = elevations[s.cloud.ring[i]] * kPi / 180.0;
            const double azimuth = 2.0 * kPi * columnOf(s, i, model) / model.columns;
            const Eigen::Vector3d dir =
                pose.linear() * Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth),
                                                std::cos(elevation) * std::sin(azimuth),
                                                std::sin(elevation));
            const Eigen::Vector3d origin = pose.translation();
            double expected = -1.0;  // no hit
            for (double t = 0.0; t <= model.max_range; t += 0.01) {
                const Eigen::Vector3d p = origin + t * dir;
                if (p.z() <= scene.terrainHeight(p.x(), p.y())) {
                    expected = t;
                    break;
                }
            }
            const double range = sensorPoint(s, i).norm();
            const bool hit = s.gt.cls[i] != GtClass::NoReturn;
            if (hit != (expected >= 0.0) || (hit && std::abs(range - expected) > 0.02)) {
                ++disagreements;
            }
        }
        // Grazing rays may skim a crest between samples of either march.
        EXPECT_LE(disagreements, 2);
    }
}

// Grass (a GroundCover) is terrain: its returns are Ground at heights within its canopy, about
// return_fraction of them off the soil; outside it the terrain is bare.
TEST(Sim, GroundCoverReturnsFromItsCanopy) {
    Scene scene = travel::sim::flatGround();
    travel::sim::GroundCover grass;
    grass.lo = {2.0, -30.0};
    grass.hi = {30.0, 30.0};
    grass.height = 0.4;
    grass.return_fraction = 0.5;
    scene.covers.push_back(grass);
    const Eigen::Isometry3d pose = levelPose(scene);
    const Scan s = scan(scene, LidarModel::vlp16(900), pose);
    std::size_t inside = 0, in_canopy = 0;
    for (std::size_t i = 0; i < s.cloud.size(); ++i) {
        const Eigen::Vector3d p = pose * sensorPoint(s, i);
        ASSERT_EQ(s.gt.cls[i], GtClass::Ground);
        const float h = s.gt.height_above_ground[i];
        EXPECT_NEAR(h, p.z(), 1e-4);
        const bool covered = p.x() > 2.05 && p.x() < 29.95 && std::abs(p.y()) < 29.95;
        if (!covered && (p.x() < 1.95 || p.x() > 30.05 || std::abs(p.y()) > 30.05)) {
            EXPECT_NEAR(h, 0.0, 1e-6);
            continue;
        }
        if (!covered) continue;
        ++inside;
        EXPECT_GE(h, -1e-6);
        EXPECT_LE(h, 0.4 + 1e-6);
        in_canopy += h > 0.01f;
    }
    ASSERT_GT(inside, 500u);
    EXPECT_NEAR(static_cast<double>(in_canopy) / inside, 0.5, 0.1);
}

// A puddle returns nothing from its water but the rays it mirrors onto something in range (a
// trunk beyond it): those are placed along the original ray, below the water (Reflection).
TEST(Sim, PuddleMirrorsOrSwallowsTheRays) {
    Scene scene = travel::sim::flatGround();
    travel::sim::Puddle puddle;
    puddle.centre = {6.0, 0.0};
    puddle.radius = 2.0;
    puddle.depth = 0.1;
    puddle.rim_height = 0.03;
    puddle.mirror_fraction = 0.5;
    scene.puddles.push_back(puddle);
    travel::sim::Pole trunk;
    trunk.centre = {9.0, 0.0};
    trunk.radius = 0.4;
    trunk.height = 4.0;
    scene.poles.push_back(trunk);
    const double level = scene.waterLevel(0);
    EXPECT_NEAR(level, -0.03, 1e-12);
    const Eigen::Isometry3d pose = levelPose(scene);
    const Scan s = scan(scene, LidarModel::hdl64(), pose);
    std::size_t mirrored = 0;
    for (std::size_t i = 0; i < s.cloud.size(); ++i) {
        const Eigen::Vector3d p = pose * sensorPoint(s, i);
        const double from_centre = (p.head<2>() - puddle.centre).norm();
        // The bowl lies below the water within 1.67 m of the centre: no terrain is seen there.
        if (s.gt.cls[i] == GtClass::Ground) {
            EXPECT_GT(from_centre, 1.6);
        }
        if (s.gt.cls[i] != GtClass::Reflection) continue;
        ++mirrored;
        EXPECT_LT(p.z(), level);
        EXPECT_EQ(s.gt.instance[i], 0u);
    }
    EXPECT_GT(mirrored, 20u);
}

}  // namespace
