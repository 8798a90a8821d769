// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// travel::compareFrames and RegressionReport (travel-regress's comparison) on synthetic frames:
// a run against itself, renumbered clusters (no difference), class changes, split and merged
// clusters, terrain nodes, the verdict against the tolerances, and frame pairing.
#include <gtest/gtest.h>

#include <sstream>

#include "travel/eval/LabelComparison.hpp"
#include "travel/viz/BirdsEye.hpp"

namespace {

using travel::FrameComparison;
using travel::LabelledFrame;
using travel::PointClass;

constexpr uint8_t kGround = static_cast<uint8_t>(PointClass::Ground);
constexpr uint8_t kNonGround = static_cast<uint8_t>(PointClass::NonGround);

/// 40 ground points, then three clusters of 20 non-ground points (ids 1, 2, 3), then 10
/// unclustered non-ground points; two traversable nodes and one that is not.
LabelledFrame syntheticFrame() {
    LabelledFrame f;
    const auto add = [&](uint8_t label, uint32_t cluster) {
        const float k = static_cast<float>(f.x.size());
        f.x.push_back(0.1f * k), f.y.push_back(0.05f * k), f.z.push_back(0.f);
        f.intensity.push_back(1.f);
        f.labels.push_back(label);
        f.clusterId.push_back(cluster);
    };
    for (int i = 0; i < 40; ++i) add(kGround, 0);
    for (uint32_t c = 1; c <= 3; ++c)
        for (int i = 0; i < 20; ++i) add(kNonGround, c);
    for (int i = 0; i < 10; ++i) add(kNonGround, 0);
    f.clusters.resize(3);
    for (uint32_t c = 0; c < 3; ++c) f.clusters[c].id = c + 1, f.clusters[c].num_points = 20;
    f.terrain.resolution = 2.f, f.terrain.cells_per_side = 4, f.terrain.origin_xy = -4.f;
    for (uint32_t index : {0u, 5u, 9u}) {
        travel::TerrainNodeRecord node;
        node.index = index;
        node.traversable = index != 9;
        f.terrain.nodes.push_back(node);
    }
    f.timings.ground_total = 2, f.timings.objects_total = 1;
    return f;
}

TEST(LabelComparison, FrameAgainstItselfIsIdentical) {
    const LabelledFrame f = syntheticFrame();
    const FrameComparison c = travel::compareFrames(f, f);
    EXPECT_FALSE(c.size_mismatch);
    EXPECT_EQ(c.class_changed, 0u);
    EXPECT_DOUBLE_EQ(c.class_agreement, 100.0);
    EXPECT_EQ(c.confusion[kGround][kGround], 40u);
    EXPECT_EQ(c.confusion[kNonGround][kNonGround], 70u);
    EXPECT_EQ(c.golden_clusters, 3u);
    EXPECT_EQ(c.run_clusters, 3u);
    EXPECT_EQ(c.matched_clusters, 3u);
    EXPECT_EQ(c.clustered_points, 60u);
    EXPECT_DOUBLE_EQ(c.cluster_agreement, 100.0);
    EXPECT_EQ(c.split + c.merged + c.changed_nodes, 0u);
    EXPECT_EQ(c.golden_traversable, 2u);
    EXPECT_EQ(c.badness(), 0.0);
}

TEST(LabelComparison, RenumberingClustersIsNoDifference) {
    const LabelledFrame golden = syntheticFrame();
    LabelledFrame run = golden;
    const uint32_t new_id[] = {0, 3, 1, 7};  // 1 -> 3, 2 -> 1, 3 -> 7 (ids need not be dense)
    for (uint32_t& id : run.clusterId) id = new_id[id];
    const FrameComparison c = travel::compareFrames(golden, run);
    EXPECT_DOUBLE_EQ(c.cluster_agreement, 100.0);
    EXPECT_EQ(c.matched_clusters, 3u);
    EXPECT_EQ(c.split, 0u);
    EXPECT_EQ(c.merged, 0u);
    EXPECT_EQ(c.badness(), 0.0);

    travel::RegressionReport report;
    report.addCompared({1, 0.1, "lidar_travel"}, c);
    EXPECT_TRUE(report.verdict(travel::RegressSection{}).passed);
}

TEST(LabelComparison, ClassChangesAreCountedPerClass) {
    const LabelledFrame golden = syntheticFrame();
    LabelledFrame run = golden;
    for (int i = 0; i < 4; ++i) run.labels[i] = kNonGround;  // ground -> non-ground
    run.labels[100] = kGround;                               // unclustered non-ground -> ground
    const FrameComparison c = travel::compareFrames(golden, run);
    EXPECT_EQ(c.class_changed, 5u);
    EXPECT_EQ(c.confusion[kGround][kNonGround], 4u);
    EXPECT_EQ(c.confusion[kNonGround][kGround], 1u);
    EXPECT_NEAR(c.class_agreement, 100.0 * 105 / 110, 1e-9);
    const std::vector<uint8_t> changed = travel::classChanges(golden, run);
    ASSERT_EQ(changed.size(), golden.size());
    EXPECT_EQ(changed[0] + changed[3] + changed[100], 3);
    EXPECT_EQ(changed[4], 0);

    travel::RegressionReport report;
    report.addCompared({1, 0.1, "lidar_travel"}, c);
    travel::RegressSection tolerances;
    const travel::RegressionVerdict strict = report.verdict(tolerances);
    EXPECT_FALSE(strict.passed);
    EXPECT_NE(strict.line.find("FAIL"), std::string::npos);
    tolerances.min_class_agreement = 95;
    EXPECT_TRUE(report.verdict(tolerances).passed) << report.verdict(tolerances).line;
    std::ostringstream md;
    report.writeMarkdown(md, "t", tolerances, {});
    EXPECT_NE(md.str().find("ground -> nonground 4"), std::string::npos) << md.str();
}

TEST(LabelComparison, SplitAndMergedClusters) {
    const LabelledFrame golden = syntheticFrame();
    LabelledFrame run = golden;
    // Golden cluster 1 (points 40..59) cut in two equal halves: split (no strict majority).
    for (std::size_t i = 50; i < 60; ++i) run.clusterId[i] = 9;
    // Golden clusters 2 and 3 (points 60..99) in one run cluster: both merged.
    for (std::size_t i = 80; i < 100; ++i) run.clusterId[i] = 2;
    const FrameComparison c = travel::compareFrames(golden, run);
    EXPECT_EQ(c.split, 1u);
    EXPECT_EQ(c.merged, 2u);
    EXPECT_EQ(c.run_clusters, 3u);
    // One-to-one: {1: 10 of 1}, {2: 20 of 2} matched; 3 and 9 left over.
    EXPECT_EQ(c.matched_clusters, 2u);
    EXPECT_EQ(c.matched_points, 30u);
    EXPECT_NEAR(c.cluster_agreement, 50.0, 1e-9);
    EXPECT_EQ(c.class_changed, 0u);

    // A lost cluster (all its points unclustered) is split, not merged.
    LabelledFrame lost = golden;
    for (std::size_t i = 40; i < 60; ++i) lost.clusterId[i] = 0;
    const FrameComparison l = travel::compareFrames(golden, lost);
    EXPECT_EQ(l.split, 1u);
    EXPECT_EQ(l.merged, 0u);
}

TEST(LabelComparison, TraversableNodesThatChanged) {
    const LabelledFrame golden = syntheticFrame();
    LabelledFrame run = golden;
    run.terrain.nodes[1].traversable = false;  // node 5
    travel::TerrainNodeRecord extra;
    extra.index = 12, extra.traversable = true;
    run.terrain.nodes.push_back(extra);
    EXPECT_EQ(travel::compareFrames(golden, run).changed_nodes, 2u);
    run = golden;
    run.terrain.resolution = 3.f;  // another grid: every traversable node differs
    EXPECT_EQ(travel::compareFrames(golden, run).changed_nodes, 4u);
}

TEST(LabelComparison, DifferentPointCountsAreAMismatch) {
    const LabelledFrame golden = syntheticFrame();
    LabelledFrame run = golden;
    run.labels.pop_back(), run.clusterId.pop_back(), run.x.pop_back();
    const FrameComparison c = travel::compareFrames(golden, run);
    EXPECT_TRUE(c.size_mismatch);
    EXPECT_EQ(c.class_agreement, 0.0);
    EXPECT_TRUE(travel::classChanges(golden, run).empty());
}

TEST(LabelComparison, MissingAndExtraFramesFailAndAreListed) {
    const LabelledFrame f = syntheticFrame();
    travel::RegressionReport report;
    report.addCompared({1, 0.1, "a_travel"}, travel::compareFrames(f, f));
    report.addMissing({2, 0.2, "a_travel"});
    report.addExtra({3, 0.3, "b_travel"});
    travel::RegressSection tolerances;
    const travel::RegressionVerdict v = report.verdict(tolerances);
    EXPECT_FALSE(v.passed);
    EXPECT_EQ(v.failures.size(), 2u) << v.line;
    tolerances.max_missing_frames = tolerances.max_extra_frames = 1;
    EXPECT_TRUE(report.verdict(tolerances).passed);
    std::ostringstream csv;
    report.writeCsv(csv);
    std::string line;
    std::istringstream lines(csv.str());
    std::getline(lines, line);
    const auto columns = std::count(line.begin(), line.end(), ',');
    int rows = 0;
    while (std::getline(lines, line)) {
        EXPECT_EQ(std::count(line.begin(), line.end(), ','), columns) << line;
        ++rows;
    }
    EXPECT_EQ(rows, 3);
    EXPECT_NE(csv.str().find(",missing,0.200000,a_travel"), std::string::npos);
    EXPECT_NE(csv.str().find(",extra,0.300000,b_travel"), std::string::npos);
}

TEST(LabelComparison, EmptyComparisonFails) {
    travel::RegressionReport report;
    EXPECT_FALSE(report.verdict(travel::RegressSection{}).passed);
}

TEST(LabelComparison, FramePairingMatchesOutOfOrder) {
    travel::FramePairing<int> pairing;
    pairing.waitGolden({2, 0.2, "a"}, 20);
    pairing.waitGolden({1, 0.1, "b"}, 11);
    int frame = 0;
    EXPECT_FALSE(pairing.takeGolden({1, 0.1, "a"}, frame));  // same time, other sensor
    EXPECT_TRUE(pairing.takeGolden({1, 0.1, "b"}, frame));
    EXPECT_EQ(frame, 11);
    EXPECT_EQ(pairing.waitingGolden().size(), 1u);
}

TEST(LabelComparison, DifferencePictureMarksChangedPoints) {
    const LabelledFrame golden = syntheticFrame();
    std::vector<uint8_t> changed(golden.size(), 0);
    travel::viz::BirdsEyeOptions opt;
    opt.size_px = 200, opt.metres_per_pixel = 0.1, opt.legend = false, opt.scale_bar = false;
    opt.range_rings = false, opt.sensor_marker = false;
    const auto count_black = [](const travel::viz::Raster& r) {
        std::size_t n = 0;
        for (std::size_t i = 0; i < r.rgb.size(); i += 3)
            n += r.rgb[i] == 0 && r.rgb[i + 1] == 0 && r.rgb[i + 2] == 0;
        return n;
    };
    const std::size_t before =
        count_black(travel::viz::renderClassChanges(golden, changed, opt).raster);
    changed[45] = 1;
    const std::size_t after =
        count_black(travel::viz::renderClassChanges(golden, changed, opt).raster);
    EXPECT_GT(after, before);
    changed.pop_back();
    EXPECT_THROW(travel::viz::renderClassChanges(golden, changed, opt), std::invalid_argument);
}

}  // namespace
