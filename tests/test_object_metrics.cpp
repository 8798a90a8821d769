// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Object segmentation scores (OSE / USE, instance coverage / purity) on hand-built frames with
// known answers, and a sanity run on real SemanticKITTI frames (skipped when absent).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "travel/eval/KittiIO.hpp"
#include "travel/eval/MergeDiagnostics.hpp"
#include "travel/eval/ObjectMetrics.hpp"

namespace fs = std::filesystem;

namespace travel {
namespace {

constexpr uint32_t kCar = 10, kPerson = 30, kBuilding = 50, kVegetation = 70, kRoad = 40;
constexpr PointClass G = PointClass::Ground;
constexpr PointClass N = PointClass::NonGround;

struct Frame {
    std::vector<float> x, y, z;
    std::vector<uint32_t> gt, cluster;
    std::vector<PointClass> pred;

    // `count` points spaced 0.1 m along x from (x0, y0, 1).
    void add(std::size_t count, float x0, float y0, uint32_t semantic, uint32_t instance,
             uint32_t cluster_id, PointClass cls = N) {
        for (std::size_t k = 0; k < count; ++k) {
            x.push_back(x0 + 0.1f * static_cast<float>(k)), y.push_back(y0), z.push_back(1.f);
            gt.push_back(semantic | (instance << 16));
            cluster.push_back(cluster_id);
            pred.push_back(cls);
        }
    }
    ObjectScores eval(const ObjectEvalOptions& options = {}) const {
        return evaluateObjects(cluster, pred, gt, x, y, z, options);
    }
};

void expectNoNaN(const ObjectScores& s) {
    const SegmentationEntropy& h = s.entropy;
    for (double v : {h.ose_sum, h.use_sum, h.ose_mean, h.use_mean, s.mean_coverage, s.mean_purity})
        EXPECT_TRUE(std::isfinite(v));
    for (const InstanceScore& i : s.instances) {
        EXPECT_TRUE(std::isfinite(i.coverage));
        EXPECT_TRUE(std::isfinite(i.purity));
    }
}

void expectAllZero(const ObjectScores& s) {
    expectNoNaN(s);
    EXPECT_EQ(s.entropy.ose_sum, 0.0);
    EXPECT_EQ(s.entropy.use_sum, 0.0);
    EXPECT_EQ(s.entropy.ose_mean, 0.0);
    EXPECT_EQ(s.entropy.use_mean, 0.0);
    EXPECT_EQ(s.entropy.num_gt_objects, 0u);
    EXPECT_EQ(s.entropy.num_clusters, 0u);
    EXPECT_TRUE(s.instances.empty());
    EXPECT_EQ(s.mean_coverage, 0.0);
    EXPECT_EQ(s.mean_purity, 0.0);
    EXPECT_EQ(s.clustered + s.split + s.merged, 0u);
}

TEST(ObjectMetrics, PerfectSegmentation) {
    Frame f;
    f.add(60, 0, 0, kCar, 1, 1);
    f.add(60, 0, 20, kCar, 2, 2);
    f.add(40, 0, -20, kBuilding, 0, 3);
    f.add(30, 0, 40, kRoad, 0, 0, G);
    const ObjectScores s = f.eval();
    expectNoNaN(s);
    EXPECT_EQ(s.entropy.ose_sum, 0.0);
    EXPECT_EQ(s.entropy.use_sum, 0.0);
    EXPECT_EQ(s.entropy.num_gt_objects, 3u);
    EXPECT_EQ(s.entropy.num_clusters, 3u);
    EXPECT_EQ(s.entropy.num_points, 160u);
    ASSERT_EQ(s.instances.size(), 2u);  // the building is not a thing
    for (const InstanceScore& i : s.instances) {
        EXPECT_EQ(i.semantic, kCar);
        EXPECT_EQ(i.points, 60u);
        EXPECT_EQ(i.coverage, 1.0);
        EXPECT_EQ(i.purity, 1.0);
        EXPECT_EQ(i.best_cluster, i.instance);
    }
    EXPECT_EQ(s.mean_coverage, 1.0);
    EXPECT_EQ(s.mean_purity, 1.0);
    EXPECT_EQ(s.clustered, 2u);
    EXPECT_EQ(s.split, 0u);
    EXPECT_EQ(s.merged, 0u);
}

TEST(ObjectMetrics, ObjectSplitInHalf) {
    Frame f;
    f.add(30, 0, 0, kCar, 1, 5);
    f.add(30, 3, 0, kCar, 1, 6);  // same object: 3.0 m continues the 0.1 m spacing
    const ObjectScores s = f.eval();
    EXPECT_EQ(s.entropy.num_gt_objects, 1u);
    EXPECT_EQ(s.entropy.num_clusters, 2u);
    EXPECT_NEAR(s.entropy.ose_sum, std::log(2.0), 1e-12);
    EXPECT_NEAR(s.entropy.ose_mean, std::log(2.0), 1e-12);
    EXPECT_EQ(s.entropy.use_sum, 0.0);
    ASSERT_EQ(s.instances.size(), 1u);
    EXPECT_EQ(s.instances[0].coverage, 0.5);
    EXPECT_EQ(s.instances[0].purity, 1.0);
    EXPECT_EQ(s.instances[0].best_cluster, 5u);  // tie: the smaller id
    EXPECT_EQ(s.split, 1u);                      // no cluster holds a strict majority
    EXPECT_EQ(s.merged, 0u);
}

TEST(ObjectMetrics, TwoObjectsMergedInOneCluster) {
    Frame f;
    f.add(60, 0, 0, kCar, 1, 7);
    f.add(60, 0, 10, kPerson, 2, 7);
    const ObjectScores s = f.eval();
    EXPECT_EQ(s.entropy.num_gt_objects, 2u);
    EXPECT_EQ(s.entropy.num_clusters, 1u);
    EXPECT_EQ(s.entropy.ose_sum, 0.0);
    EXPECT_NEAR(s.entropy.use_sum, std::log(2.0), 1e-12);
    EXPECT_NEAR(s.entropy.use_mean, std::log(2.0), 1e-12);
    ASSERT_EQ(s.instances.size(), 2u);
    for (const InstanceScore& i : s.instances) {
        EXPECT_EQ(i.coverage, 1.0);
        EXPECT_EQ(i.purity, 0.5);
    }
    EXPECT_EQ(s.merged, 2u);
    EXPECT_EQ(s.split, 0u);
}

TEST(ObjectMetrics, PurityCountsEveryPointOfTheCluster) {
    Frame f;
    f.add(60, 0, 0, kCar, 1, 1);
    f.add(180, 0, 0.3f, kRoad, 0, 1, G);  // ground-labelled points wrongly in cluster 1
    f.add(20, 0, 30, kRoad, 0, 2, G);     // a cluster without any object point
    const ObjectScores s = f.eval();
    ASSERT_EQ(s.instances.size(), 1u);
    EXPECT_EQ(s.instances[0].coverage, 1.0);
    EXPECT_EQ(s.instances[0].purity, 0.25);
    EXPECT_EQ(s.merged, 1u);
    // USE only sees scored (object) points: cluster 1 is pure there, cluster 2 has none.
    EXPECT_EQ(s.entropy.use_sum, 0.0);
    EXPECT_EQ(s.entropy.num_clusters, 1u);
}

TEST(ObjectMetrics, UnclusteredPointsAreSingletons) {
    Frame f;
    f.add(30, 0, 0, kCar, 1, 1);
    f.add(30, 3, 0, kCar, 1, 0);
    ObjectScores s = f.eval();
    // 30 singletons of share 1/60 and one label of share 1/2.
    const double expected = 30.0 / 60.0 * std::log(60.0) + 0.5 * std::log(2.0);
    EXPECT_NEAR(s.entropy.ose_sum, expected, 1e-12);
    EXPECT_EQ(s.entropy.use_sum, 0.0);
    EXPECT_EQ(s.entropy.num_clusters, 1u);
    ASSERT_EQ(s.instances.size(), 1u);
    EXPECT_EQ(s.instances[0].coverage, 0.5);
    EXPECT_EQ(s.instances[0].purity, 1.0);

    // A fully dropped object: OSE = ln N, coverage 0, purity 0 and out of the purity mean.
    Frame g;
    g.add(60, 0, 0, kCar, 1, 0);
    g.add(60, 0, 10, kCar, 2, 4);
    s = g.eval();
    EXPECT_NEAR(s.entropy.ose_sum, std::log(60.0), 1e-12);
    EXPECT_NEAR(s.entropy.ose_mean, std::log(60.0) / 2, 1e-12);
    EXPECT_EQ(s.entropy.num_gt_objects, 2u);
    EXPECT_EQ(s.entropy.num_clusters, 1u);
    ASSERT_EQ(s.instances.size(), 2u);
    EXPECT_EQ(s.instances[0].best_cluster, 0u);
    EXPECT_EQ(s.instances[0].coverage, 0.0);
    EXPECT_EQ(s.instances[0].purity, 0.0);
    EXPECT_EQ(s.clustered, 1u);
    EXPECT_EQ(s.mean_coverage, 0.5);
    EXPECT_EQ(s.mean_purity, 1.0);
    EXPECT_EQ(s.split, 1u);
    EXPECT_EQ(s.merged, 0u);
}

TEST(ObjectMetrics, PredictedGroundPointsAndTheEntropyOption) {
    Frame f;
    f.add(30, 0, 0, kCar, 1, 1);
    f.add(30, 3, 0, kCar, 1, 0, G);  // the car's lower half predicted ground
    ObjectScores s = f.eval();
    EXPECT_EQ(s.entropy.num_points, 30u);  // only the predicted non-ground points are scored
    EXPECT_EQ(s.entropy.ose_sum, 0.0);
    ASSERT_EQ(s.instances.size(), 1u);
    EXPECT_EQ(s.instances[0].coverage, 0.5);  // coverage counts every point of the instance

    ObjectEvalOptions all;
    all.entropy_on_predicted_nonground = false;
    s = f.eval(all);
    EXPECT_EQ(s.entropy.num_points, 60u);
    EXPECT_NEAR(s.entropy.ose_sum, 0.5 * std::log(60.0) + 0.5 * std::log(2.0), 1e-12);
}

TEST(ObjectMetrics, EmptyFrame) {
    const Frame f;
    expectAllZero(f.eval());
    EXPECT_TRUE(groundTruthObjects({}, {}, {}, {}).empty());
}

TEST(ObjectMetrics, FrameWithoutObjects) {
    Frame f;
    f.add(100, 0, 0, kRoad, 0, 0, G);
    f.add(50, 0, 5, kRoad, 0, 3, N);  // a cluster on ground-truth ground
    f.add(40, 0, 10, 0, 0, 4, N);     // unlabeled
    f.add(40, 0, 15, 1, 0, 0, N);     // outlier
    expectAllZero(f.eval());
}

TEST(ObjectMetrics, SmallInstancesAndObjectsAreIgnored) {
    Frame f;
    f.add(49, 0, 0, kCar, 1, 1);
    f.add(50, 0, 10, kCar, 2, 2);
    f.add(9, 0, 20, kPerson, 3, 0);  // below min_gt_object_points: not in OSE
    ObjectScores s = f.eval();
    ASSERT_EQ(s.instances.size(), 1u);
    EXPECT_EQ(s.instances[0].instance, 2u);
    EXPECT_EQ(s.entropy.num_gt_objects, 2u);
    EXPECT_EQ(s.entropy.ose_sum, 0.0);

    ObjectEvalOptions o;
    o.min_gt_object_points = 1;
    o.min_instance_points = 1;
    s = f.eval(o);
    EXPECT_EQ(s.instances.size(), 3u);
    EXPECT_EQ(s.entropy.num_gt_objects, 3u);
    EXPECT_NEAR(s.entropy.ose_sum, std::log(9.0), 1e-12);
}

TEST(ObjectMetrics, GroundTruthObjectsAreEuclideanClusters) {
    Frame f;
    f.add(20, 0, 0, kBuilding, 0, 1);
    f.add(20, 10, 0, kBuilding, 0, 1);      // far away, same (class, instance 0)
    f.add(20, 0, 0.2f, kVegetation, 0, 2);  // touches the first group, other class
    ObjectScores s = f.eval();
    EXPECT_EQ(s.entropy.num_gt_objects, 3u);
    EXPECT_EQ(s.entropy.num_clusters, 2u);
    EXPECT_EQ(s.entropy.ose_sum, 0.0);
    EXPECT_NEAR(s.entropy.use_sum, std::log(2.0), 1e-12);  // cluster 1 holds two objects

    const std::vector<uint32_t> obj = groundTruthObjects(f.gt, f.x, f.y, f.z);
    ASSERT_EQ(obj.size(), 60u);
    for (std::size_t i = 0; i < 60; ++i) EXPECT_EQ(obj[i], i / 20 + 1) << i;

    // Single linkage at 0.5 m: a chain of 0.4 m steps is one object, 0.6 m steps are not.
    Frame chain;
    for (int k = 0; k < 12; ++k) chain.add(1, 0.4f * static_cast<float>(k), 0, kBuilding, 0, 1);
    for (int k = 0; k < 12; ++k) chain.add(1, 0.6f * static_cast<float>(k), 5, kBuilding, 0, 1);
    ObjectEvalOptions one;
    one.min_gt_object_points = 1;
    const std::vector<uint32_t> c = groundTruthObjects(chain.gt, chain.x, chain.y, chain.z, one);
    for (int k = 0; k < 12; ++k) EXPECT_EQ(c[k], 1u);
    for (int k = 0; k < 12; ++k) EXPECT_EQ(c[12 + k], 2u + k);
}

// Brute-force single-linkage clustering, O(n^2), to check the voxel-grid search.
std::vector<uint32_t> bruteForceObjects(const Frame& f, double d) {
    const std::size_t n = f.x.size();
    std::vector<uint32_t> id(n, 0);
    uint32_t next = 0;
    for (std::size_t s = 0; s < n; ++s) {
        if (id[s] != 0 || (f.gt[s] & 0xFFFF) == kRoad) continue;
        id[s] = ++next;
        std::vector<std::size_t> stack{s};
        while (!stack.empty()) {
            const std::size_t q = stack.back();
            stack.pop_back();
            for (std::size_t j = 0; j < n; ++j) {
                if (id[j] != 0 || f.gt[j] != f.gt[q]) continue;
                const double dx = double(f.x[j]) - f.x[q], dy = double(f.y[j]) - f.y[q],
                             dz = double(f.z[j]) - f.z[q];
                if (dx * dx + dy * dy + dz * dz <= d * d) id[j] = next, stack.push_back(j);
            }
        }
    }
    return id;
}

Frame randomFrame(unsigned seed, std::size_t n, float extent = 6.f) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> pos(-extent, extent);
    std::uniform_int_distribution<int> cls(0, 3), inst(0, 15), cl(0, 6);
    const uint32_t classes[] = {kCar, kBuilding, kVegetation, kRoad};
    Frame f;
    for (std::size_t i = 0; i < n; ++i) {
        const uint32_t c = classes[cls(rng)];
        f.x.push_back(pos(rng)), f.y.push_back(pos(rng)), f.z.push_back(0.2f * pos(rng));
        f.gt.push_back(c | (static_cast<uint32_t>(inst(rng)) << 16));
        f.cluster.push_back(static_cast<uint32_t>(cl(rng)));
        f.pred.push_back(c == kRoad ? G : N);
    }
    return f;
}

TEST(ObjectMetrics, GridClusteringMatchesBruteForce) {
    for (unsigned seed = 1; seed <= 3; ++seed) {
        const Frame f = randomFrame(seed, 3000);
        ObjectEvalOptions o;
        o.min_gt_object_points = 1;
        o.gt_cluster_distance = 0.7;
        EXPECT_EQ(groundTruthObjects(f.gt, f.x, f.y, f.z, o), bruteForceObjects(f, 0.7));
    }
}

TEST(ObjectMetrics, Deterministic) {
    const Frame f = randomFrame(42, 20000, 2.f);  // dense: objects percolate
    const ObjectScores a = f.eval(), b = f.eval();
    EXPECT_GT(a.entropy.num_gt_objects, 10u);
    EXPECT_GT(a.instances.size(), 10u);
    EXPECT_EQ(a.entropy.ose_sum, b.entropy.ose_sum);
    EXPECT_EQ(a.entropy.use_sum, b.entropy.use_sum);
    EXPECT_EQ(a.entropy.num_gt_objects, b.entropy.num_gt_objects);
    EXPECT_EQ(a.mean_coverage, b.mean_coverage);
    EXPECT_EQ(a.mean_purity, b.mean_purity);
    ASSERT_EQ(a.instances.size(), b.instances.size());
    for (std::size_t k = 0; k < a.instances.size(); ++k) {
        EXPECT_EQ(a.instances[k].instance, b.instances[k].instance);
        EXPECT_EQ(a.instances[k].best_cluster, b.instances[k].best_cluster);
        EXPECT_EQ(a.instances[k].purity, b.instances[k].purity);
    }
    expectNoNaN(a);
}

TEST(ObjectMetrics, InvalidInputsThrow) {
    Frame f;
    f.add(10, 0, 0, kCar, 1, 1);
    std::vector<uint32_t> short_clusters(9, 1);
    EXPECT_THROW(evaluateObjects(short_clusters, f.pred, f.gt, f.x, f.y, f.z),
                 std::invalid_argument);
    std::vector<PointClass> short_pred(9, N);
    EXPECT_THROW(evaluateObjects(f.cluster, short_pred, f.gt, f.x, f.y, f.z),
                 std::invalid_argument);
    std::vector<float> short_z(9, 0.f);
    EXPECT_THROW(evaluateObjects(f.cluster, f.pred, f.gt, f.x, f.y, short_z),
                 std::invalid_argument);
    EXPECT_THROW(groundTruthObjects(f.gt, f.x, f.y, short_z), std::invalid_argument);
    ObjectEvalOptions bad;
    bad.gt_cluster_distance = 0;
    EXPECT_THROW(f.eval(bad), std::invalid_argument);
    bad.gt_cluster_distance = std::nan("");
    EXPECT_THROW(f.eval(bad), std::invalid_argument);
}

TEST(ObjectMetrics, NonFinitePointsAreNotGroundTruthObjects) {
    Frame f;
    f.add(20, 0, 0, kBuilding, 0, 1);
    f.x[3] = std::nanf("");
    f.z[7] = INFINITY;
    const std::vector<uint32_t> obj = groundTruthObjects(f.gt, f.x, f.y, f.z);
    EXPECT_EQ(obj[3], 0u);
    EXPECT_EQ(obj[7], 0u);
    EXPECT_EQ(obj[0], 1u);
    expectNoNaN(f.eval());
}

TEST(ObjectMetrics, AccumulatorPoolsInstancesOverFrames) {
    Frame a;  // 1 instance, coverage 1
    a.add(60, 0, 0, kCar, 1, 1);
    Frame b;  // 3 instances, coverage 0.5 each, OSE ln 2 each
    for (uint32_t k = 0; k < 3; ++k) {
        b.add(30, 0, 10.f * k, kCar, k + 1, 2 * k + 1);
        b.add(30, 3, 10.f * k, kCar, k + 1, 2 * k + 2);
    }
    ObjectScoreAccumulator acc;
    EXPECT_EQ(acc.summary().mean_coverage, 0.0);  // nothing yet: zeros
    acc.add(a.eval());
    acc.add(b.eval());
    const ObjectSummary s = acc.summary();
    EXPECT_EQ(s.frames, 2u);
    EXPECT_EQ(s.instances, 4u);
    EXPECT_EQ(s.clustered, 4u);
    EXPECT_DOUBLE_EQ(s.mean_coverage, (1.0 + 3 * 0.5) / 4);  // not (1 + 0.5) / 2
    EXPECT_EQ(s.mean_purity, 1.0);
    EXPECT_EQ(s.split, 3u);
    EXPECT_EQ(s.gt_objects, 4u);
    EXPECT_EQ(s.clusters, 7u);
    EXPECT_NEAR(s.ose_per_frame, 3 * std::log(2.0) / 2, 1e-12);
    EXPECT_NEAR(s.ose_per_object, 3 * std::log(2.0) / 4, 1e-12);
    EXPECT_EQ(s.use_per_cluster, 0.0);
}

// Real frames: the ground truth itself as the prediction must score perfectly.
const fs::path kSequence = fs::path(TRAVEL_DATA_DIR) / "semantickitti/sequences/00";

TEST(ObjectMetrics, RealKittiGroundTruthAsPrediction) {
    if (!fs::exists(kSequence / "labels" / "000002.label"))
        GTEST_SKIP() << "SemanticKITTI frames not found in " << kSequence
                     << " (../shared/data is not part of the repository)";
    PointCloud cloud;
    std::size_t total_instances = 0;
    for (int frame = 0; frame < 3; ++frame) {
        char name[16];
        std::snprintf(name, sizeof name, "%06d", frame);
        readScan((kSequence / "velodyne" / (std::string(name) + ".bin")).string(), cloud,
                 ScanFormat::KittiBin);
        const std::vector<uint32_t> gt = readLabelFile(
            (kSequence / "labels" / (std::string(name) + ".label")).string(), cloud.size());
        std::vector<PointClass> pred(cloud.size(), G);
        std::vector<uint32_t> thing_ids(cloud.size(), 0);
        for (std::size_t i = 0; i < cloud.size(); ++i) {
            const uint32_t semantic = gt[i] & 0xFFFF, instance = gt[i] >> 16;
            if (semantic > 1 && semantic != 40 && semantic != 44 && semantic != 48 &&
                semantic != 49 && semantic != 60 && semantic != 72)
                pred[i] = N;
            const bool thing = (semantic >= 10 && semantic <= 32) || semantic >= 252;
            if (thing && instance != 0) thing_ids[i] = instance;
        }
        // Instances: the GT instance id as the cluster id.
        const ObjectScores s = evaluateObjects(thing_ids, pred, gt, cloud);
        std::printf("frame %s: %zu thing instances with >= 50 points\n", name, s.instances.size());
        total_instances += s.instances.size();
        EXPECT_EQ(s.mean_coverage, 1.0);
        EXPECT_EQ(s.mean_purity, 1.0);
        EXPECT_EQ(s.split + s.merged, 0u);
        EXPECT_EQ(s.clustered, s.instances.size());

        // Entropies: the GT objects as the clusters.
        const auto t0 = std::chrono::steady_clock::now();
        const std::vector<uint32_t> objects = groundTruthObjects(gt, cloud.x, cloud.y, cloud.z);
        const ObjectScores e = evaluateObjects(objects, pred, gt, cloud);
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count();
        std::printf("frame %s: %zu GT objects over %zu points, %.1f ms for both calls\n", name,
                    e.entropy.num_gt_objects, e.entropy.num_points, ms);
        EXPECT_GT(e.entropy.num_gt_objects, 20u);
        EXPECT_EQ(e.entropy.ose_sum, 0.0);
        EXPECT_EQ(e.entropy.use_sum, 0.0);
        EXPECT_EQ(e.entropy.num_clusters, e.entropy.num_gt_objects);
    }
    std::printf("frames 000000-000002: %zu thing instances with >= 50 points\n", total_instances);
    EXPECT_EQ(total_instances, 33u);
}

// travel-eval merges' merges.md: every table's delimiter row has one cell per header column
// (the third table's title holds three columns), or Markdown renders it as plain text.
TEST(MergeTable, MarkdownTablesHaveOneDelimiterCellPerColumn) {
    eval::MergedPart part;
    part.cluster = 1;
    part.owner_semantic = kVegetation;
    part.part_semantic = kCar;
    part.part_points = 12;
    part.range = 15;
    eval::MergeTable table;
    table.add({part});
    std::istringstream md(table.markdown());
    std::string line, header;
    int tables = 0;
    while (std::getline(md, line)) {
        if (line.rfind("|---", 0) == 0) {
            ++tables;
            EXPECT_EQ(std::count(line.begin(), line.end(), '|'),
                      std::count(header.begin(), header.end(), '|'))
                << header << "\n"
                << line;
        }
        header = line;
    }
    EXPECT_EQ(tables, 3);
}

}  // namespace
}  // namespace travel
