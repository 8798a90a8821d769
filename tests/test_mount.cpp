// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The sensor mount configures itself (MountEstimator, Pipeline with `auto` values) and a wrong
// configured mount is reported (MountNote), on synthetic scans from known mounts.
//
// Thresholds: height within 0.05 m and roll/pitch within 0.5 deg. The simulated range noise is
// 0.01 m and thousands of ground points enter the least-squares refit, so the statistical error
// is a few millimetres and hundredths of a degree; the margin is for the estimator's real
// biases (object bases inside the inlier band, bumpy terrain). 0.05 m is well inside eps3
// (ground_dist 0.13 m) and 0.5 deg is a tenth of the 5 deg warning tolerance; the test that
// matters downstream is the second one: `auto` labels the scene like the true values (1 %).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "travel/MountEstimator.hpp"
#include "travel/Pipeline.hpp"
#include "travel/sim/Scenes.hpp"
#include "travel/sim/SyntheticLidar.hpp"

namespace travel {
namespace {

constexpr double kHeightTolerance = 0.05;  // m
constexpr double kAngleToleranceDeg = 0.5;
constexpr double kMaxLabelDifference = 0.01;  // share of all points

struct Mount {
    double height, roll_deg, pitch_deg;
};

std::string describe(const Mount& m) {
    return "height " + std::to_string(m.height) + " roll " + std::to_string(m.roll_deg) +
           " pitch " + std::to_string(m.pitch_deg);
}

sim::LidarModel testLidar() {
    sim::LidarModel model = sim::LidarModel::hdl64();
    model.range_noise_sigma = 0.01;
    model.seed = 11;
    model.max_range = Params{}.max_range;
    return model;
}

// The vehicle stands level on the scene's ground at the origin; the sensor is `m.height` above
// it with the mount's roll and pitch.
sim::Scan scanFrom(const sim::Scene& scene, const Mount& m) {
    return sim::scan(scene, testLidar(),
                     sim::sensorPoseAt(scene, 0, 0, m.height, m.roll_deg, m.pitch_deg, 0));
}

const std::vector<Mount>& mounts() {
    static const std::vector<Mount> all = {
        {0.5, 0, 0},  {1.73, 0, 0},  {2.5, 0, 0}, {1.73, 3, 0}, {1.73, -3, 0},
        {1.73, 0, 3}, {1.73, 0, -3}, {2.5, 6, 0}, {0.5, 0, 6},  {2.5, -3, 3},
    };
    return all;
}

class EveryMount : public ::testing::TestWithParam<int> {};

TEST_P(EveryMount, EstimateIsCloseToTheTrueMount) {
    const Mount m = mounts()[GetParam()];
    SCOPED_TRACE(describe(m));
    for (const sim::Scene& scene : {sim::flatGround(), sim::urbanObjects()}) {
        const sim::Scan scan = scanFrom(scene, m);
        MountEstimator estimator;
        const GroundPlaneEstimate g =
            estimator.estimate(scan.cloud, Eigen::Vector3d::UnitZ(), 2.7, 80.0);
        ASSERT_TRUE(g.found);
        EXPECT_NEAR(g.height, m.height, kHeightTolerance);
        EXPECT_NEAR(g.roll_deg, m.roll_deg, kAngleToleranceDeg);
        EXPECT_NEAR(g.pitch_deg, m.pitch_deg, kAngleToleranceDeg);
        EXPECT_GT(g.num_inliers, 1000u);
    }
}

TEST_P(EveryMount, AutoLabelsLikeTheTrueValues) {
    const Mount m = mounts()[GetParam()];
    SCOPED_TRACE(describe(m));
    const sim::Scan scan = scanFrom(sim::urbanObjects(), m);

    Params truth;
    truth.sensor_height = m.height;
    truth.mount_roll_deg = m.roll_deg;
    truth.mount_pitch_deg = m.pitch_deg;
    Params automatic;  // defaults (1.73 m, level) are only the fallbacks
    automatic.sensor_height = AutoReal::makeAuto(1.73);
    automatic.mount_roll_deg = AutoReal::makeAuto(0.0);
    automatic.mount_pitch_deg = AutoReal::makeAuto(0.0);

    Result with_truth, with_auto;
    Pipeline(truth).process(scan.cloud, {}, with_truth);
    Pipeline pipeline(automatic);
    pipeline.process(scan.cloud, {}, with_auto);

    ASSERT_EQ(with_auto.mount.kind, MountNote::Kind::Estimated) << with_auto.mount.message;
    EXPECT_NE(with_auto.mount.message.find("sensor_height auto: "), std::string::npos);
    EXPECT_NE(with_auto.mount.message.find("(from frame 0, "), std::string::npos);
    EXPECT_FALSE(pipeline.params().sensor_height.isAuto());
    EXPECT_NEAR(pipeline.params().sensor_height, m.height, kHeightTolerance);
    // The result carries the height used (the estimate), for FrameFusion and the evaluation.
    EXPECT_EQ(with_auto.sensor_height, double(pipeline.params().sensor_height));
    EXPECT_EQ(with_truth.sensor_height, m.height);
    EXPECT_EQ(with_truth.mount.kind, MountNote::Kind::None) << with_truth.mount.message;

    std::size_t differ = 0;
    for (std::size_t i = 0; i < scan.cloud.size(); ++i)
        differ += with_auto.labels[i] != with_truth.labels[i];
    EXPECT_LE(double(differ), kMaxLabelDifference * double(scan.cloud.size()))
        << differ << " of " << scan.cloud.size() << " labels differ";

    // Kept: the next frame is not estimated again and reports nothing.
    Result next;
    pipeline.process(scan.cloud, {}, next);
    EXPECT_EQ(next.mount.kind, MountNote::Kind::None);
    EXPECT_EQ(next.labels, with_auto.labels);
}

INSTANTIATE_TEST_SUITE_P(Mounts, EveryMount, ::testing::Range(0, int(mounts().size())));

// -j N: a worker's pipeline is built before the first frame, then takes the first pipeline's
// settled state (its estimated mount): it labels the next frames like that pipeline and like
// settledCopy(), and unlike its own unsettled self.
TEST(MountCheck, PipelineBuiltEarlyTakesTheSettledStateOfAnother) {
    const Mount m{1.2, 3.0, -2.0};
    const sim::Scan scan = scanFrom(sim::urbanObjects(), m);
    Params automatic;
    automatic.sensor_height = AutoReal::makeAuto(1.73);
    automatic.mount_roll_deg = AutoReal::makeAuto(0.0);
    automatic.mount_pitch_deg = AutoReal::makeAuto(0.0);
    Pipeline first(automatic), early(automatic), unsettled(automatic);
    Result settled_result, early_result, copy_result;
    first.process(scan.cloud, {}, settled_result);
    ASSERT_TRUE(first.mountSettled());
    ASSERT_EQ(settled_result.mount.kind, MountNote::Kind::Estimated);

    early.adoptSettledState(first);
    EXPECT_TRUE(early.mountSettled());
    EXPECT_EQ(double(early.params().sensor_height), double(first.params().sensor_height));
    early.process(scan.cloud, {}, early_result);
    EXPECT_EQ(early_result.mount.kind, MountNote::Kind::None);  // nothing estimated again
    EXPECT_EQ(early_result.labels, settled_result.labels);
    EXPECT_EQ(early_result.cluster_id, settled_result.cluster_id);
    first.settledCopy().process(scan.cloud, {}, copy_result);
    EXPECT_EQ(copy_result.labels, early_result.labels);

    // Without the state it would estimate again (a note on its first frame).
    Result own;
    unsettled.process(scan.cloud, {}, own);
    EXPECT_EQ(own.mount.kind, MountNote::Kind::Estimated);
}

TEST(MountCheck, WrongHeightWarnsOnceWithTheMeasuredValue) {
    const sim::Scan scan = scanFrom(sim::urbanObjects(), {1.73, 0, 0});
    Params wrong;
    wrong.sensor_height = 0.5;
    Pipeline pipeline(wrong);
    Result result;
    pipeline.process(scan.cloud, {}, result);
    ASSERT_EQ(result.mount.kind, MountNote::Kind::Mismatch);
    EXPECT_TRUE(result.mount.isWarning());
    const std::string& message = result.mount.message;
    EXPECT_NE(message.find("sensor_height is 0.50 m but the ground is 1.7"), std::string::npos)
        << message;
    EXPECT_NE(message.find("set sensor_height: 1.7"), std::string::npos) << message;
    EXPECT_NE(message.find(" or auto"), std::string::npos) << message;
    // The check of configured values fits a 1-in-4 sample; its count says so.
    EXPECT_NE(message.find(" ground points in a 1-in-4 sample)"), std::string::npos) << message;
    pipeline.process(scan.cloud, {}, result);
    EXPECT_EQ(result.mount.kind, MountNote::Kind::None);  // once
}

TEST(MountCheck, TrueHeightDoesNotWarn) {
    for (const double h : {0.5, 1.73, 2.5}) {
        const sim::Scan scan = scanFrom(sim::urbanObjects(), {h, 0, 0});
        Params right;
        right.sensor_height = h;
        Result result;
        Pipeline(right).process(scan.cloud, {}, result);
        EXPECT_EQ(result.mount.kind, MountNote::Kind::None) << h << ": " << result.mount.message;
    }
}

// A cloud in a base frame (origin on the ground under the sensor): the ground labels are those
// of the sensor frame, the clusters are not (docs/input-contract.md), so the first frame warns,
// with a fixed sensor_height 0 and with `auto` (which then takes 0 m, the ground's height).
TEST(MountCheck, BaseFrameCloudWarns) {
    const sim::Scan scan = scanFrom(sim::urbanObjects(), {1.73, 0, 0});
    Params fixed;
    fixed.sensor_height = 0.0;
    fixed.min_range = 1.0;
    Params automatic = fixed;
    automatic.sensor_height = AutoReal::makeAuto(1.73);
    Params sensor_height_given = fixed;
    sensor_height_given.sensor_height = 1.73;
    // The first frame's note for `params` on the scan with its origin `down` below the sensor,
    // and the sensor_height then used.
    const auto firstNote = [&](const Params& params, float down, double& height_used) {
        PointCloud cloud = scan.cloud;
        for (float& z : cloud.z) z += down;
        Pipeline pipeline(params);
        Result result;
        pipeline.process(cloud, {}, result);
        height_used = pipeline.params().sensor_height;
        return result.mount;
    };
    double height = -1.0;
    for (const Params& params : {fixed, automatic}) {
        const MountNote note = firstNote(params, 1.73f, height);
        ASSERT_EQ(note.kind, MountNote::Kind::Mismatch) << note.message;
        EXPECT_NE(note.message.find("within 0.20 m of the ground"), std::string::npos)
            << note.message;
        EXPECT_NE(note.message.find("give the points in the sensor frame"), std::string::npos);
        EXPECT_GE(height, 0.0);
        EXPECT_LT(height, 0.05);
        EXPECT_EQ(params.sensor_height.isAuto(),
                  note.message.find("sensor_height auto: 0.0") != std::string::npos)
            << note.message;
    }
    // The ground 0.1 m above the origin (a base frame's origin under its ground): found, `auto`
    // takes 0 m, and a fixed 1.73 m is not told to become the base frame's height.
    for (const Params& params : {automatic, sensor_height_given}) {
        const MountNote note = firstNote(params, 1.83f, height);
        ASSERT_EQ(note.kind, MountNote::Kind::Mismatch) << note.message;
        EXPECT_NE(note.message.find("(-0.10 m above it)"), std::string::npos) << note.message;
        EXPECT_EQ(note.message.find("set sensor_height"), std::string::npos) << note.message;
        EXPECT_EQ(height, params.sensor_height.isAuto() ? 0.0 : 1.73);
    }
    // The scan in its sensor frame does not warn (nor a sensor 0.5 m up:
    // MountCheck.TrueHeightDoesNotWarn).
    EXPECT_EQ(firstNote(sensor_height_given, 0.f, height).kind, MountNote::Kind::None);
}

TEST(MountCheck, WrongTiltWarnsWithTheAnglesToSet) {
    const sim::Scan scan = scanFrom(sim::flatGround(), {1.73, 0, 6});
    Result result;
    Pipeline(Params{}).process(scan.cloud, {}, result);
    ASSERT_EQ(result.mount.kind, MountNote::Kind::Mismatch);
    EXPECT_NE(result.mount.message.find("mount_pitch_deg: 6.0"), std::string::npos)
        << result.mount.message;
    EXPECT_EQ(result.mount.message.find("sensor_height is"), std::string::npos);
}

TEST(MountCheck, NoGroundNoEstimate) {
    // Every point 3 m above the sensor: no plane below it.
    PointCloud cloud;
    for (int i = 0; i < 2000; ++i) {
        const double a = i * 0.01;
        cloud.x.push_back(float(10 * std::cos(a)));
        cloud.y.push_back(float(10 * std::sin(a)));
        cloud.z.push_back(3.f);
    }
    MountEstimator estimator;
    EXPECT_FALSE(estimator.estimate(cloud, Eigen::Vector3d::UnitZ(), 0.5, 80).found);
}

TEST(MountEstimate, LeavesTheOwnVehicleOut) {
    // The self box is tested in the vehicle frame: with the sensor yawed +90 deg, the sensor's
    // -y axis is the vehicle's +x (a box ahead of the vehicle).
    Params params;
    params.mount_yaw_deg = 90.0;
    params.self_box_min_x = 1.0, params.self_box_max_x = 3.0;
    params.self_box_min_y = -0.5, params.self_box_max_y = 0.5;
    params.self_box_min_z = -1.0, params.self_box_max_z = 1.0;
    PointCloud probe;
    for (const auto& p : {Eigen::Vector3f(0, -2, 0), Eigen::Vector3f(2, 0, 0)})
        probe.x.push_back(p.x()), probe.y.push_back(p.y()), probe.z.push_back(p.z());
    std::vector<uint8_t> is_self;
    markSelfReturns(probe, params, is_self);
    ASSERT_EQ(is_self.size(), 2u);
    EXPECT_EQ(is_self[0], 1);  // vehicle (2, 0, 0): inside
    EXPECT_EQ(is_self[1], 0);  // vehicle (0, -2, 0): beside it

    // The estimate skips excluded points: with every point excluded there is no ground.
    const sim::Scan scan = scanFrom(sim::flatGround(), Mount{1.73, 0, 0});
    MountEstimator estimator;
    EXPECT_TRUE(estimator.estimate(scan.cloud, Eigen::Vector3d::UnitZ(), 2.7, 80.0).found);
    const std::vector<uint8_t> all(scan.cloud.size(), 1);
    EXPECT_FALSE(
        estimator.estimate(scan.cloud, Eigen::Vector3d::UnitZ(), 2.7, 80.0, all.data()).found);
    // An empty box marks nothing (and costs no per-point buffer).
    markSelfReturns(scan.cloud, Params{}, is_self);
    EXPECT_TRUE(is_self.empty());
}

TEST(FirstGroundRing, SeedSearchReachesIt) {
    // MRPT's VLP-16 sample: 2.24 m up, lowest beam -15 deg: first ground ring at 8.36 m.
    EXPECT_NEAR(firstGroundRingRadius(2.24, -15.0, 4.0), 2.24 / std::tan(15 * M_PI / 180) + 2.0,
                1e-9);
    EXPECT_EQ(firstGroundRingRadius(2.24, 1.0, 4.0), 0.0);  // no beam points down
    Params p;
    p.elevation_table = "vlp16";
    p.num_rings = 16;
    p.tgf_resolution = 2.0;
    p.seed_search_radius = 5.0;
    p.sensor_height = 2.5;
    EXPECT_NEAR(Pipeline(p).params().seed_search_radius, 2.5 / std::tan(15 * M_PI / 180) + 1.0,
                1e-9);
    p.seed_search_radius = 20.0;  // a larger configured radius stays
    EXPECT_EQ(Pipeline(p).params().seed_search_radius, 20.0);
    EXPECT_EQ(Pipeline(Params{}).params().seed_search_radius, Params{}.seed_search_radius);
}

}  // namespace
}  // namespace travel
