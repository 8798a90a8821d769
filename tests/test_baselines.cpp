// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The evaluation baselines (travel::eval) on synthetic scenes: they should behave as their
// papers describe, including where they fail (one RANSAC plane cannot follow a ramp), and obey
// the common contract (every point labelled, cluster ids 1..K by first point, deterministic).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include "SceneMetrics.hpp"
#include "travel/Errors.hpp"
#include "travel/Pipeline.hpp"
#include "travel/Preprocessing.hpp"
#include "travel/eval/Segmenter.hpp"
#include "travel/sim/Scenes.hpp"
#include "travel/sim/SyntheticLidar.hpp"

namespace travel {
namespace {

constexpr double kSensorHeight = 1.73;

Params testParams() {
    Params params;
    params.sensor_height = kSensorHeight;
    return params;
}

sim::Scan scanOf(const sim::Scene& scene, bool emit_no_returns = false) {
    sim::LidarModel lidar = sim::LidarModel::hdl64();
    lidar.range_noise_sigma = 0.01;
    lidar.seed = 7;
    lidar.max_range = Params{}.max_range;
    lidar.emit_no_returns = emit_no_returns;
    return sim::scan(scene, lidar, sim::sensorPoseAt(scene, 0, 0, kSensorHeight, 0, 0, 0));
}

eval::Segmentation run(const std::string& method, const sim::Scan& scan) {
    eval::Segmentation out;
    eval::makeSegmenter(method, testParams())->segment(scan.cloud, out);
    return out;
}

// Ground recall over the true ground points whose x lies in [x_min, x_max) (the sensor is at
// the world origin with yaw 0, so sensor x is world x up to the noise).
double groundRecall(const sim::Scan& scan, const eval::Segmentation& seg, double x_min,
                    double x_max) {
    std::size_t truth = 0, found = 0;
    for (std::size_t i = 0; i < scan.gt.size(); ++i) {
        if (scan.gt.cls[i] != sim::Ground) continue;
        if (scan.cloud.x[i] < x_min || scan.cloud.x[i] >= x_max) continue;
        ++truth;
        found += seg.labels[i] == PointClass::Ground;
    }
    return truth ? double(found) / double(truth) : 0.0;
}

using test::ObjectScore;

ObjectScore scoreObject(const sim::Scan& scan, const eval::Segmentation& seg, uint32_t instance) {
    return test::scoreObject(scan.gt, seg.labels, seg.cluster_id, instance);
}

TEST(Baselines, UnknownMethodIsAConfigErrorNamingTheValidOnes) {
    try {
        eval::makeSegmenter("patchwork", testParams());
        FAIL() << "no exception";
    } catch (const ConfigError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("patchwork"), std::string::npos) << message;
        for (const std::string& name : eval::methodNames())
            EXPECT_NE(message.find(name), std::string::npos) << name << " missing: " << message;
    }
    EXPECT_EQ(eval::methodNames().size(), 9u);
}

TEST(Baselines, NamesAreTheFactoryNames) {
    for (const std::string& name : eval::methodNames())
        EXPECT_EQ(eval::makeSegmenter(name, testParams())->name(), name);
}

TEST(Baselines, GroundF1OnFlatGround) {
    const sim::Scan scan = scanOf(sim::flatGround());
    for (const char* method : {"ransac", "gpf", "tgs"}) {
        const test::SceneScores s = test::scoreScene(scan.gt, run(method, scan).labels);
        std::printf("[ flat ] %-6s P %.4f R %.4f F1 %.4f\n", method, s.precision(), s.recall(),
                    s.f1());
        EXPECT_GE(s.f1(), 0.95) << method;
    }
}

TEST(Baselines, OnePlaneMissesA20DegreeRampThatTgsKeeps) {
    // Ramp from x = 6 m to 21 m rising 5.5 m, then a plateau. RANSAC fits the near flat ground
    // only. GPF fits one plane per segment along x (equal point counts), but with the paper's
    // three segments the forward one starts a few metres ahead, on flat ground: its lowest
    // points and seeds are there, and three PCA iterations with Th_dist = 0.2 m stay on the
    // flat. Measured (HDL-64E, seed 7): ramp recall RANSAC 0.266, GPF 0.278, TGS 0.970; GPF
    // with 10 segments 0.42. TGS follows the ramp node by node.
    const sim::Scan scan = scanOf(sim::slope(20));
    std::map<std::string, double> ramp;
    for (const char* method : {"ransac", "gpf", "tgs"}) {
        const eval::Segmentation seg = run(method, scan);
        ramp[method] = groundRecall(scan, seg, 6.0, 21.0);
        const test::SceneScores s = test::scoreScene(scan.gt, seg.labels);
        std::printf("[slope20] %-6s ramp recall %.3f plateau recall %.3f  F1 %.4f\n", method,
                    ramp[method], groundRecall(scan, seg, 21.0, 1e9), s.f1());
    }
    EXPECT_LT(ramp["ransac"], 0.5);
    EXPECT_LT(ramp["gpf"], 0.5);  // the paper's failure mode, not ours to fix
    EXPECT_GE(ramp["tgs"], 0.95);
}

TEST(Baselines, ClusterersSeparateTwoCarsOneMetreApartAndKeepPolesWhole) {
    // Cars 1 and 2 stand side by side with a 1 m gap: wider than Th_run (0.5 m) and the 0.5 m
    // Euclidean tolerance, so both clusterers keep them apart.
    const sim::Scan scan = scanOf(sim::urbanObjects());
    for (const char* method : {"gpf+slr", "tgs+slr", "tgs+euclidean", "gpf+euclidean"}) {
        SCOPED_TRACE(method);
        const eval::Segmentation seg = run(method, scan);
        const ObjectScore a = scoreObject(scan, seg, 1), b = scoreObject(scan, seg, 2);
        std::printf("[urban] %-14s car1 cov %.3f pur %.3f  car2 cov %.3f pur %.3f", method,
                    a.coverage, a.purity, b.coverage, b.purity);
        ASSERT_GT(a.points, 100u);
        ASSERT_GT(b.points, 100u);
        EXPECT_NE(a.best_cluster, b.best_cluster);
        EXPECT_GE(a.purity, 0.95);
        EXPECT_GE(b.purity, 0.95);
        EXPECT_GE(a.coverage, 0.9);
        EXPECT_GE(b.coverage, 0.9);
        for (const uint32_t pole : {4u, 5u, 6u}) {
            const ObjectScore p = scoreObject(scan, seg, pole);
            std::printf("  pole%u cov %.3f pur %.3f", pole, p.coverage, p.purity);
            ASSERT_GT(p.points, 30u) << "pole " << pole;
            EXPECT_GE(p.coverage, 0.95) << "pole " << pole;
            EXPECT_GE(p.purity, 0.95) << "pole " << pole;
        }
        std::printf("\n");
    }
}

TEST(Baselines, EveryMethodLabelsEveryPointAndNumbersClusters1ToK) {
    sim::Scan scan = scanOf(sim::mixed(), /*emit_no_returns=*/true);
    // Non-finite and out-of-range points must be Invalid too.
    const float nan = std::numeric_limits<float>::quiet_NaN();
    scan.cloud.x[5] = nan;
    scan.cloud.y[6] = std::numeric_limits<float>::infinity();
    scan.cloud.x[7] = 500.f;
    AlignedCloud aligned;
    preprocess(scan.cloud, testParams(), {}, aligned);
    ASSERT_LT(aligned.num_valid, scan.cloud.size());

    const Params params = testParams();
    for (const std::string& method : eval::methodNames()) {
        SCOPED_TRACE(method);
        const auto segmenter = eval::makeSegmenter(method, params);
        eval::Segmentation seg, again;
        segmenter->segment(scan.cloud, seg);
        ASSERT_EQ(seg.labels.size(), scan.cloud.size());
        ASSERT_EQ(seg.cluster_id.size(), scan.cloud.size());
        std::map<uint32_t, std::size_t> size;
        std::map<uint32_t, std::size_t> first;
        std::size_t ground = 0;
        for (std::size_t i = 0; i < scan.cloud.size(); ++i) {
            EXPECT_EQ(seg.labels[i] == PointClass::Invalid, aligned.valid[i] == 0) << i;
            ground += seg.labels[i] == PointClass::Ground;
            const uint32_t id = seg.cluster_id[i];
            if (id == 0) continue;
            EXPECT_EQ(seg.labels[i], PointClass::NonGround) << i;
            if (!size.count(id)) first[id] = i;
            ++size[id];
        }
        EXPECT_GT(ground, scan.cloud.size() / 4);
        const bool clusters =
            method.find('+') != std::string::npos || method.rfind("travel", 0) == 0;
        EXPECT_EQ(!size.empty(), clusters);
        if (!size.empty()) {
            EXPECT_EQ(size.rbegin()->first, size.size());  // ids 1..K
        }
        for (const auto& [id, count] : size) {
            EXPECT_GE(count, static_cast<std::size_t>(params.min_cluster_size)) << id;
            if (id > 1) {
                EXPECT_LT(first[id - 1], first[id]) << id;  // ordered by first point
            }
        }
        // Deterministic: the same instance again, and a fresh one.
        segmenter->segment(scan.cloud, again);
        EXPECT_EQ(again.labels, seg.labels);
        EXPECT_EQ(again.cluster_id, seg.cluster_id);
        eval::makeSegmenter(method, params)->segment(scan.cloud, again);
        EXPECT_EQ(again.labels, seg.labels);
        EXPECT_EQ(again.cluster_id, seg.cluster_id);
        EXPECT_GE(seg.ground_ms, 0.0);
        EXPECT_EQ(seg.objects_ms > 0.0, clusters);
    }
}

TEST(Baselines, TravelMethodsAreThePipeline) {
    const sim::Scan scan = scanOf(sim::mixed());
    Params params = testParams();
    Result result;
    Pipeline(params).process(scan.cloud, {}, result);
    const eval::Segmentation travel = run("travel", scan), tgs = run("tgs", scan);
    EXPECT_EQ(travel.labels, result.labels);
    EXPECT_EQ(travel.cluster_id, result.cluster_id);
    EXPECT_EQ(tgs.labels, result.labels);
    // tgs+slr and tgs+euclidean cluster TGS's own non-ground points.
    EXPECT_EQ(run("tgs+slr", scan).labels, result.labels);
    EXPECT_EQ(run("tgs+euclidean", scan).labels, result.labels);
    params.ttmf = false;
    Pipeline(params).process(scan.cloud, {}, result);
    EXPECT_EQ(run("travel-no-ttmf", scan).labels, result.labels);
}

}  // namespace
}  // namespace travel
