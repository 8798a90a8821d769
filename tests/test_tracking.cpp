// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// travel::Tracker on hand-made clusters: life of a track, ids, velocity, moving flag,
// association gates and determinism; the `tracking` configuration section.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "travel/ConfigIO.hpp"
#include "travel/Errors.hpp"
#include "travel/tracking/TrackShapeAlignment.hpp"
#include "travel/tracking/Tracker.hpp"

namespace {

travel::ClusterSummary box(double x, double y, double length = 4.0, double width = 1.8,
                           double height = 1.5) {
    travel::ClusterSummary c;
    c.num_points = 500;
    c.centroid = Eigen::Vector3f(float(x), float(y), float(height / 2 - 1.7));
    c.aabb_min =
        c.centroid - Eigen::Vector3f(float(length / 2), float(width / 2), float(height / 2));
    c.aabb_max =
        c.centroid + Eigen::Vector3f(float(length / 2), float(width / 2), float(height / 2));
    c.obb_center = c.centroid;
    c.obb_extent = Eigen::Vector3f(float(length), float(width), float(height));
    return c;
}

const Eigen::Isometry3d kIdentity = Eigen::Isometry3d::Identity();

}  // namespace

TEST(ConstantVelocityModel, RecoversAConstantVelocity) {
    travel::ConstantVelocityModel m;
    m.start({0, 0}, 0.2, 5.0);
    for (int k = 1; k <= 30; ++k) {
        m.predict(0.1, 1.0);
        m.correct(Eigen::Vector2d(0.8 * k, -0.3 * k), 0.2);
    }
    EXPECT_NEAR(m.velocity().x(), 8.0, 0.05);
    EXPECT_NEAR(m.velocity().y(), -3.0, 0.05);
    EXPECT_LT(m.velocityCovariance()(0, 0), 0.5);
}

TEST(ConstantVelocityModel, AnisotropicMeasurementLeavesTheLooseAxisToThePrediction) {
    // Settled at 7 m/s along x; then measured precisely in y (a side seen across) and loosely
    // in x, where the measurements slide back by 5 cm a frame (a centroid over the side).
    travel::ConstantVelocityModel m;
    m.start({0, 0}, 0.5, 5.0);
    for (int k = 1; k <= 30; ++k) m.predict(0.1, 0.5), m.correct({0.7 * k, 0.0}, 0.2);
    Eigen::Matrix2d noise = Eigen::Matrix2d::Zero();
    noise.diagonal() << 1.3 * 1.3, 0.03 * 0.03;
    for (int k = 31; k <= 40; ++k)
        m.predict(0.1, 0.5), m.correct(Eigen::Vector2d(0.7 * k - 0.05 * (k - 30), 0.0), noise);
    EXPECT_NEAR(m.velocity().x(), 7.0, 0.1);  // 6.96; 6.70 with the 0.2 m isotropic noise
    EXPECT_NEAR(m.velocity().y(), 0.0, 0.01);
}

TEST(TrackAssociation, GatesAndTieOrder) {
    travel::WorldBox a;
    a.centre = {0, 0};
    a.min = {-1, -1, -1};
    a.max = {1, 1, 1};
    a.size = 2;
    travel::WorldBox far = a;
    far.centre = {5, 0};
    far.min.x() += 5;
    far.max.x() += 5;
    const travel::AssociationGates gates;
    EXPECT_LT(travel::gatedDistance(a, far, far.centre, gates), 0);  // too far
    travel::WorldBox huge = a;
    huge.size = 10;
    EXPECT_LT(travel::gatedDistance(a, huge, huge.centre, gates), 0);  // size ratio
    EXPECT_EQ(travel::gatedDistance(a, a, a.centre, gates), 0);
    // Two tracks at the same distance of one cluster: the first track takes it.
    std::vector<travel::AssociationPair> pairs;
    std::vector<int> t2c, c2t;
    const std::vector<travel::WorldBox> tracks{a, a}, clusters{a};
    travel::associateNearest(
        2, 1,
        [&](uint32_t t, uint32_t c) {
            return travel::gatedDistance(tracks[t], clusters[c], clusters[c].centre, gates);
        },
        pairs, t2c, c2t);
    EXPECT_EQ(t2c[0], 0);
    EXPECT_EQ(t2c[1], -1);
    EXPECT_EQ(c2t[0], 0);
}

TEST(Tracker, ConfirmsNamesAndEndsTracks) {
    travel::TrackingParams p;
    travel::Tracker tracker(p);
    for (int k = 0; k < 10; ++k) {
        std::vector<travel::ClusterSummary> clusters{box(10, 0), box(-5, 8)};
        tracker.update(0.1 * k, kIdentity, clusters);
        const uint32_t expected0 = k + 1 >= p.confirm_hits ? 1u : 0u;
        const uint32_t expected1 = k + 1 >= p.confirm_hits ? 2u : 0u;
        EXPECT_EQ(clusters[0].track_id, expected0) << k;
        EXPECT_EQ(clusters[1].track_id, expected1) << k;
        EXPECT_FALSE(clusters[0].moving);
    }
    // The second object disappears for max_misses - 1 frames and comes back: same id.
    for (int k = 10; k < 10 + p.max_misses - 1; ++k) {
        std::vector<travel::ClusterSummary> clusters{box(10, 0)};
        tracker.update(0.1 * k, kIdentity, clusters);
        EXPECT_EQ(clusters[0].track_id, 1u);
    }
    std::vector<travel::ClusterSummary> back{box(10, 0), box(-5, 8)};
    tracker.update(0.1 * (10 + p.max_misses - 1), kIdentity, back);
    EXPECT_EQ(back[1].track_id, 2u);
    // Gone for max_misses frames: ended; a new object gets a new id.
    double t = 0.1 * (10 + p.max_misses);
    for (int k = 0; k < p.max_misses; ++k, t += 0.1) {
        std::vector<travel::ClusterSummary> clusters{box(10, 0)};
        tracker.update(t, kIdentity, clusters);
    }
    for (int k = 0; k < p.confirm_hits; ++k, t += 0.1) {
        std::vector<travel::ClusterSummary> clusters{box(10, 0), box(-5, 8)};
        tracker.update(t, kIdentity, clusters);
        if (k + 1 == p.confirm_hits) {
            EXPECT_EQ(clusters[1].track_id, 3u);
        }
    }
}

TEST(Tracker, VelocityAndMovingFlagInAMovingEgoFrame) {
    // Ego drives at 10 m/s along x and turns at 0.2 rad/s; a car drives at 5 m/s along world y
    // and a parked car stands at (30, 5). Velocities come back in the aligned axes.
    travel::Tracker tracker;
    for (int k = 0; k < 40; ++k) {
        const double t = 0.1 * k;
        Eigen::Isometry3d world_T_aligned = Eigen::Isometry3d::Identity();
        world_T_aligned.translation() = Eigen::Vector3d(10 * t, 0, 0);
        world_T_aligned.linear() = Eigen::AngleAxisd(0.2 * t, Eigen::Vector3d::UnitZ()).matrix();
        const Eigen::Isometry3d aligned_T_world = world_T_aligned.inverse();
        const Eigen::Vector3d moving_world(20, -10 + 5 * t, 0);
        const Eigen::Vector3d parked_world(30, 5, 0);
        const Eigen::Vector3d m = aligned_T_world * moving_world;
        const Eigen::Vector3d s = aligned_T_world * parked_world;
        std::vector<travel::ClusterSummary> clusters{box(m.x(), m.y()), box(s.x(), s.y())};
        tracker.update(t, world_T_aligned, clusters);
        if (k < 15) continue;
        const Eigen::Vector3d v_world =
            world_T_aligned.linear() * clusters[0].velocity.cast<double>();
        EXPECT_NEAR(v_world.x(), 0.0, 0.3) << k;
        EXPECT_NEAR(v_world.y(), 5.0, 0.3) << k;
        EXPECT_TRUE(clusters[0].moving) << k;
        EXPECT_FALSE(clusters[1].moving) << k;
        EXPECT_LT(clusters[1].velocity.norm(), 0.3f) << k;
        EXPECT_GT(clusters[0].velocity_sigma.x(), 0.f);
        EXPECT_EQ(clusters[0].track_id, 1u);
        EXPECT_EQ(clusters[1].track_id, 2u);
    }
}

TEST(Tracker, SameInputSameIdsAndResetRestarts) {
    auto run = [](travel::Tracker& tracker) {
        std::vector<uint32_t> ids;
        for (int k = 0; k < 20; ++k) {
            std::vector<travel::ClusterSummary> clusters;
            for (int j = 0; j < 6; ++j)
                clusters.push_back(box(3.0 * j + 0.2 * k, j % 2 ? 4 : -4, 1, 1));
            tracker.update(0.1 * k, kIdentity, clusters);
            for (const auto& c : clusters) ids.push_back(c.track_id);
        }
        return ids;
    };
    travel::Tracker a, b;
    const auto first = run(a);
    EXPECT_EQ(first, run(b));
    a.reset();
    EXPECT_TRUE(a.tracks().empty());
    EXPECT_EQ(first, run(a));
}

TEST(Tracker, TooLongClustersAreNotTracked) {
    travel::Tracker tracker;
    for (int k = 0; k < 5; ++k) {
        std::vector<travel::ClusterSummary> clusters{box(0, 10, 150, 1)};  // > max_object_extent
        tracker.update(0.1 * k, kIdentity, clusters);
        EXPECT_EQ(clusters[0].track_id, 0u);
    }
    EXPECT_TRUE(tracker.tracks().empty());
}

TEST(TrackingSection, LoadsValidatesAndRejectsUnknownKeys) {
    travel::Config c;
    travel::applyConfigText("tracking:\n  gate_distance: 3\n  confirm_hits: 2\n", "t.yaml", c);
    c.validate();
    EXPECT_EQ(c.tracking.gate_distance, 3.0);
    EXPECT_EQ(c.tracking.confirm_hits, 2);
    travel::Config bad;
    EXPECT_THROW(travel::applyConfigText("tracking:\n  gate_distanse: 3\n", "t.yaml", bad),
                 travel::ConfigError);
    travel::applyConfigText("tracking:\n  moving_speed_off: 2\n", "t.yaml", bad);
    EXPECT_THROW(bad.validate(), travel::ConfigError);
    EXPECT_NE(travel::configToYaml(travel::Config{}).find("\ntracking:\n"), std::string::npos);
}

// ---------------------------------------------------------------- shape alignment

namespace {

/// Points on the faces y = y0 (x in [x0, x0 + 4.5]) and, if `end`, x = x0 (y in [y0, y0 + 1.8]),
/// every 0.1 m from `phase`, at three heights (scan rings): a car's side and rear as a LiDAR
/// samples them (the beams, not the car, fix where the points are).
std::vector<Eigen::Vector3d> carFaces(double x0, double y0, bool end, double phase) {
    std::vector<Eigen::Vector3d> points;
    for (const double z : {-1.0, -0.7, -0.4}) {
        for (double s = phase; s < 4.5; s += 0.1) points.emplace_back(x0 + s, y0, z);
        if (end)
            for (double s = phase; s < 1.8; s += 0.1) points.emplace_back(x0, y0 + s, z);
    }
    return points;
}

}  // namespace

TEST(TrackShape, TwoFacesGiveTheDisplacementWhateverTheCentroidSays) {
    travel::TrackShape shape;
    shape.remember(carFaces(10, 3, true, 0.0), {12, 3.5});
    // Moved by (0.4, -0.3), sampled elsewhere on the faces; the guess (a centroid's shift) is
    // 0.5 m off along the car.
    Eigen::Vector2d d;
    ASSERT_TRUE(shape.displacement(carFaces(10.4, 2.7, true, 0.05), {0.9, -0.3}, 0.5, d));
    EXPECT_NEAR(d.x(), 0.4, 0.03);
    EXPECT_NEAR(d.y(), -0.3, 0.03);
}

TEST(TrackShape, OneFaceLeavesItsLengthToTheGuess) {
    travel::TrackShape shape;
    shape.remember(carFaces(10, 3, false, 0.0), {12, 3});
    // A side seen alone says nothing along itself: x is the guess's, y the face's.
    Eigen::Vector2d d;
    ASSERT_TRUE(shape.displacement(carFaces(10.7, 3.2, false, 0.05), {0.6, 0.5}, 0.5, d));
    EXPECT_NEAR(d.x(), 0.6, 0.05);
    EXPECT_NEAR(d.y(), 0.2, 0.03);
    // ... and its information is all across the side (y): none along it.
    Eigen::Matrix2d information;
    ASSERT_TRUE(
        shape.displacement(carFaces(10.7, 3.2, false, 0.05), {0.6, 0.5}, 0.5, d, &information));
    EXPECT_GT(information(1, 1), 100.0);  // sigma < 0.1 m across
    EXPECT_NEAR(information(0, 0), 0.0, 1e-6);
    // Another object: no overlap, no displacement.
    EXPECT_FALSE(shape.displacement(carFaces(30, 20, false, 0.0), {0, 0}, 0.5, d));
}

TEST(ClusterSamples, AtMost64PointsOfClustersLongEnough) {
    travel::PointCloud cloud;
    std::vector<uint32_t> ids;
    std::vector<travel::ClusterSummary> clusters(2);
    for (int i = 0; i < 1000; ++i) {  // cluster 1: a 5 m car of 1000 points, 2: a pedestrian
        const bool car = i % 10 != 0;
        cloud.x.push_back(car ? 0.005f * i : 20.f);
        cloud.y.push_back(car ? 3.f : 0.f);
        cloud.z.push_back(0.f);
        ids.push_back(car ? 1 : 2);
    }
    clusters[0].id = 1, clusters[0].num_points = 900, clusters[0].obb_extent = {5.f, 1.8f, 1.5f};
    clusters[1].id = 2, clusters[1].num_points = 100, clusters[1].obb_extent = {0.5f, 0.5f, 1.7f};
    travel::ClusterSamples samples;
    samples.build(cloud, ids, Eigen::Matrix3f::Identity(), clusters);
    const uint32_t n = samples.end(0) - samples.begin(0);
    EXPECT_GT(n, 50u);
    EXPECT_LE(n, travel::ClusterSamples::kMaxSamples);
    EXPECT_EQ(samples.end(1), samples.begin(1));  // too short to need it
    // Spread over the whole car, not its first points.
    float lo = 1e9f, hi = -1e9f;
    for (uint32_t i = samples.begin(0); i < samples.end(0); ++i)
        lo = std::min(lo, samples.points()[i].x()), hi = std::max(hi, samples.points()[i].x());
    EXPECT_GT(hi - lo, 4.5f);
}
