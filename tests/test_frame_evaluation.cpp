// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// travel::eval::evaluateFrame and EvaluationAccumulator: the one frame evaluation behind
// travel-kitti and travel-eval. A simulated HDL-64 scan of the urban scene is written as a KITTI
// .bin with SemanticKITTI-style labels (road 40, car 10 with its instance id).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "travel/Errors.hpp"
#include "travel/eval/FrameEvaluation.hpp"
#include "travel/eval/KittiIO.hpp"
#include "travel/eval/Report.hpp"
#include "travel/sim/Scenes.hpp"
#include "travel/sim/SyntheticLidar.hpp"

namespace fs = std::filesystem;

namespace travel::eval {
namespace {

// One directory per process: ctest runs the tests of this file in parallel processes.
fs::path testDir() {
    const fs::path dir =
        fs::temp_directory_path() / ("travel_test_frame_evaluation_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

struct Files {
    std::string scan, label;
};

const Files& urbanFrame() {
    static const Files files = [] {
        const fs::path dir = testDir();
        const sim::Scene scene = sim::urbanObjects();
        const sim::Scan s = sim::scan(scene, sim::LidarModel::hdl64(),
                                      sim::sensorPoseAt(scene, 0, 0, sim::kSensorHeight, 0, 0, 0));
        std::vector<uint32_t> gt(s.cloud.size(), 0);
        for (std::size_t i = 0; i < gt.size(); ++i)
            if (s.gt.cls[i] == sim::Ground)
                gt[i] = 40;
            else if (s.gt.cls[i] == sim::NonGround)
                gt[i] = (s.gt.instance[i] << 16) | 10u;
        Files f{(dir / "000000.bin").string(), (dir / "000000.label").string()};
        writeKittiBin(f.scan, s.cloud);
        writeLabelFile(f.label, gt);
        return f;
    }();
    return files;
}

TEST(EvaluateFrame, ScoresAreTheMetricsOfTheSegmentation) {
    const Files& f = urbanFrame();
    const Params params;
    const auto segmenter = makeSegmenter("travel", params);
    FrameEvaluation frame;
    evaluateFrame(f.scan, f.label, *segmenter, frame);

    // The same scan segmented independently, scored with the metric functions directly.
    PointCloud cloud;
    readScan(f.scan, cloud);
    Segmentation expected;
    makeSegmenter("travel", params)->segment(cloud, expected);
    const std::vector<uint32_t> gt = readLabelFile(f.label, cloud.size());
    ASSERT_TRUE(frame.scored);
    ASSERT_EQ(frame.cloud.size(), cloud.size());
    EXPECT_EQ(frame.segmentation.labels, expected.labels);
    EXPECT_EQ(frame.segmentation.cluster_id, expected.cluster_id);
    EXPECT_EQ(frame.ground_truth, gt);
    for (int p = 0; p < 2; ++p) {
        const GroundScores s = scoresFrom(
            countGround(expected.labels, gt, cloud.z, expected.sensor_height, kGroundProtocols[p]));
        EXPECT_DOUBLE_EQ(frame.ground[p].f1, s.f1) << p;
        EXPECT_DOUBLE_EQ(frame.ground[p].precision, s.precision) << p;
        EXPECT_DOUBLE_EQ(frame.ground[p].recall, s.recall) << p;
        EXPECT_DOUBLE_EQ(frame.ground[p].accuracy, s.accuracy) << p;
    }
    const ObjectScores o = evaluateObjects(expected.cluster_id, expected.labels, gt, cloud);
    EXPECT_DOUBLE_EQ(frame.objects.entropy.use_sum, o.entropy.use_sum);
    EXPECT_DOUBLE_EQ(frame.objects.entropy.ose_sum, o.entropy.ose_sum);
    EXPECT_EQ(frame.objects.instances.size(), o.instances.size());
    EXPECT_EQ(frame.clusters,
              *std::max_element(expected.cluster_id.begin(), expected.cluster_id.end()));
    EXPECT_GT(frame.clusters, 0u);
    EXPECT_TRUE(frame.clustered);
    std::size_t total = 0;
    for (std::size_t c : frame.class_counts) total += c;
    EXPECT_EQ(total, cloud.size());
    EXPECT_GT(frame.ground[1].f1, 90.0);  // a flat street: TRAVEL finds its ground
}

TEST(EvaluateFrame, WithoutLabelsNothingIsScored) {
    const Params params;
    const auto segmenter = makeSegmenter("travel", params);
    FrameEvaluation frame;
    evaluateFrame(urbanFrame().scan, "", *segmenter, frame);
    EXPECT_FALSE(frame.scored);
    EXPECT_TRUE(frame.ground_truth.empty());
    EXPECT_EQ(frame.segmentation.labels.size(), frame.cloud.size());

    EvaluationAccumulator totals;
    totals.add(frame);  // unscored: not counted
    EXPECT_EQ(totals.summary().f1[0].n, 0u);
    EXPECT_FALSE(totals.summary().clusters);

    // A label file of zeros (every point unlabelled) holds no ground truth: not scored (both
    // protocols gave it 100, averaged with the frames that have ground truth).
    const std::string zeros = (testDir() / "zeros.label").string();
    writeLabelFile(zeros, std::vector<uint32_t>(frame.cloud.size(), 0));
    FrameEvaluation unlabelled, labelled;
    evaluateFrame(urbanFrame().scan, zeros, *segmenter, unlabelled);
    evaluateFrame(urbanFrame().scan, urbanFrame().label, *segmenter, labelled);
    EXPECT_FALSE(unlabelled.scored);
    EXPECT_TRUE(labelled.scored);
    for (int p = 0; p < 2; ++p) {
        EXPECT_GT(labelled.ground[p].points, 0u);
        EXPECT_LT(labelled.ground[p].f1, 100.0);
    }
    // Protocol B scores no unlabelled, outlier or vegetation point: a frame of only those
    // counts nothing there (and is not averaged in B), while A scores them.
    FrameEvaluation vegetation;
    writeLabelFile(zeros, std::vector<uint32_t>(frame.cloud.size(), 70));
    evaluateFrame(urbanFrame().scan, zeros, *segmenter, vegetation);
    EXPECT_TRUE(vegetation.scored);
    EXPECT_EQ(vegetation.ground[1].points, 0u);
    EXPECT_GT(vegetation.ground[0].points, 0u);
    EvaluationAccumulator with_vegetation;
    with_vegetation.add(labelled), with_vegetation.add(vegetation);
    EXPECT_EQ(with_vegetation.summary().f1[0].n, 2u);
    EXPECT_EQ(with_vegetation.summary().f1[1].n, 1u);
    EvaluationAccumulator both;
    both.add(labelled), both.add(unlabelled);
    for (int p = 0; p < 2; ++p) {
        EXPECT_EQ(both.summary().f1[p].n, 1u);
        EXPECT_EQ(both.summary().f1[p].mean, labelled.ground[p].f1);
    }
}

TEST(EvaluateFrame, GroundOnlyMethodsHaveNoObjectStage) {
    const Params params;
    const auto segmenter = makeSegmenter("tgs", params);
    FrameEvaluation frame;
    EvaluationAccumulator totals;
    for (int k = 0; k < 2; ++k) {
        evaluateFrame(urbanFrame().scan, urbanFrame().label, *segmenter, frame);
        totals.add(frame);
    }
    EXPECT_FALSE(frame.clustered);
    EXPECT_EQ(frame.clusters, 0u);
    const EvaluationSummary s = totals.summary();
    EXPECT_EQ(s.f1[1].n, 2u);
    EXPECT_DOUBLE_EQ(s.f1[1].mean, frame.ground[1].f1);
    EXPECT_DOUBLE_EQ(s.f1[1].std, 0.0);
    EXPECT_FALSE(s.clusters);
    EXPECT_EQ(s.objects.frames, 0u);
    EXPECT_EQ(s.use.n, 0u);
}

// Protocol A's vegetation rule uses the height the segmenter used: under `auto` the estimate,
// not the fallback (here 0.5 m, the sensor being 1.73 m above the street).
TEST(EvaluateFrame, AutoHeightIsScoredWithTheEstimate) {
    const Files& f = urbanFrame();
    PointCloud cloud;
    readScan(f.scan, cloud);
    std::vector<uint32_t> gt = readLabelFile(f.label, cloud.size());
    // Object points 0.4-1.2 m below the sensor become vegetation: ground under protocol A with
    // h = 0.5 (z < -0.375), not with h = 1.73 (z < -1.30).
    std::size_t relabelled = 0;
    for (std::size_t i = 0; i < gt.size(); ++i)
        if ((gt[i] & 0xffffu) == 10u && cloud.z[i] < -0.4f && cloud.z[i] > -1.2f)
            gt[i] = 70, ++relabelled;
    ASSERT_GT(relabelled, 100u);
    const std::string label = (testDir() / "vegetation.label").string();
    writeLabelFile(label, gt);

    Params params;
    params.sensor_height = AutoReal::makeAuto(0.5);
    const auto segmenter = makeSegmenter("travel", params);
    FrameEvaluation frame;
    evaluateFrame(f.scan, label, *segmenter, frame);
    const Segmentation& seg = frame.segmentation;
    EXPECT_NEAR(seg.sensor_height, sim::kSensorHeight, 0.1);
    const GroundScores used =
        scoresFrom(countGround(seg.labels, gt, cloud.z, seg.sensor_height, GroundProtocol::A));
    const GroundScores fallback =
        scoresFrom(countGround(seg.labels, gt, cloud.z, 0.5, GroundProtocol::A));
    EXPECT_DOUBLE_EQ(frame.ground[0].f1, used.f1);
    EXPECT_NE(frame.ground[0].f1, fallback.f1);
}

// The baselines do not estimate the mount: `auto` is refused, naming the key and the method.
TEST(EvaluateFrame, BaselinesRejectAutoMount) {
    for (const char* method : {"gpf", "ransac", "gpf+slr"}) {
        Params params;
        params.mount_pitch_deg = AutoReal::makeAuto(0.0);
        try {
            makeSegmenter(method, params);
            FAIL() << method << " accepted auto";
        } catch (const ConfigError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find("mount_pitch_deg"), std::string::npos) << what;
            EXPECT_NE(what.find(method), std::string::npos) << what;
        }
    }
    Params params;
    params.sensor_height = AutoReal::makeAuto(1.73);
    EXPECT_NO_THROW(makeSegmenter("tgs+slr", params));
}

TEST(EvaluateFrame, ErrorsNameTheFile) {
    const Params params;
    const auto segmenter = makeSegmenter("travel", params);
    FrameEvaluation frame;
    const std::string missing = (testDir() / "missing.bin").string();
    try {
        evaluateFrame(missing, "", *segmenter, frame);
        FAIL() << "no error for a missing scan";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
    }
    // A label file with the wrong number of labels.
    const std::string short_label = (testDir() / "short.label").string();
    writeLabelFile(short_label, {40, 40, 40});
    try {
        evaluateFrame(urbanFrame().scan, short_label, *segmenter, frame);
        FAIL() << "no error for a short label file";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find(short_label), std::string::npos) << e.what();
    }
}

// travel-eval sweep's leave-one-out: the value chosen without a frame is scored on it.
TEST(LeaveOneOut, ChoosesEachFoldOnTheOtherFramesAndScoresTheHeldOutOne) {
    // Per value, per frame: ground F1 (B). Value 1 is best on frames 0 and 1 but poor on frame 2;
    // value 0 is best on frame 2 alone.
    const double f1[2][3] = {{97.0, 97.0, 99.0}, {99.0, 99.0, 95.0}};
    std::vector<std::vector<eval::FrameRow>> rows(2, std::vector<eval::FrameRow>(3));
    for (int v = 0; v < 2; ++v)
        for (int f = 0; f < 3; ++f) {
            rows[v][f].frame = "00/" + std::to_string(f);
            rows[v][f].ground[1].f1 = f1[v][f];
            rows[v][f].ground[1].points = 1000;
            rows[v][f].objects = true;
            rows[v][f].instances = 2;
            rows[v][f].coverage = 0.5 + 0.1 * f;  // the same for both values: ties
        }
    const eval::LeaveOneOut loo = eval::leaveOneOut(rows, eval::SweepScore::GroundF1B);
    ASSERT_EQ(loo.folds.size(), 3u);
    // Without frame 0: value 0 has (97 + 99) / 2 = 98, value 1 has 97: value 0, scored 97.
    EXPECT_EQ(loo.folds[0].chosen, 0u);
    EXPECT_DOUBLE_EQ(loo.folds[0].held_out, 97.0);
    EXPECT_EQ(loo.folds[1].chosen, 0u);
    EXPECT_DOUBLE_EQ(loo.folds[1].held_out, 97.0);
    // Without frame 2: value 1 (99) over value 0 (97), scored 95 on frame 2.
    EXPECT_EQ(loo.folds[2].chosen, 1u);
    EXPECT_DOUBLE_EQ(loo.folds[2].held_out, 95.0);
    EXPECT_DOUBLE_EQ(loo.held_out_mean, (97.0 + 97.0 + 95.0) / 3);
    // In sample both values average 97.67 ((97 + 97 + 99) / 3 = (99 + 99 + 95) / 3): the first.
    EXPECT_EQ(loo.in_sample, 0u);
    EXPECT_NEAR(loo.in_sample_mean, 293.0 / 3, 1e-12);
    // Coverage is the same for both values: ties choose the first.
    EXPECT_EQ(eval::leaveOneOut(rows, eval::SweepScore::Coverage).folds[1].chosen, 0u);
    EXPECT_EQ(eval::parseSweepScore("purity"), eval::SweepScore::Purity);
    // The key as --set writes it (travel.KEY) is the same key; other sections are refused.
    EXPECT_EQ(eval::parseSweep("travel.tgf_resolution=2,4", Params{}).key, "tgf_resolution");
    EXPECT_THROW(eval::parseSweep("map.resolution=0.1,0.2", Params{}), ConfigError);
    EXPECT_THROW(eval::parseSweepScore("f2"), ConfigError);
    EXPECT_THROW(eval::leaveOneOut({{rows[0][0]}}, eval::SweepScore::GroundF1B),
                 std::invalid_argument);
}

// A frame without ground truth (labels all unlabeled) or without thing instances has no score:
// it is left out of the folds and means, not averaged in as F1 or coverage 0.
TEST(LeaveOneOut, FramesWithoutAScoreAreLeftOut) {
    std::vector<std::vector<eval::FrameRow>> rows(2, std::vector<eval::FrameRow>(3));
    const double f1[2][3] = {{97.0, 0.0, 99.0}, {99.0, 0.0, 95.0}};
    for (int v = 0; v < 2; ++v)
        for (int f = 0; f < 3; ++f) {
            eval::FrameRow& row = rows[v][f];
            row.frame = "00/" + std::to_string(f);
            row.ground[1].f1 = f1[v][f];
            row.ground[1].points = f == 1 ? 0 : 1000;  // frame 1: nothing to score
            row.objects = true;
            row.instances = f == 2 ? 0 : 3;  // frame 2: no thing instance
            row.coverage = f == 2 ? 0.0 : 0.9;
        }
    EXPECT_EQ(eval::scoredFrames(rows, eval::SweepScore::GroundF1B),
              (std::vector<std::size_t>{0, 2}));
    const eval::LeaveOneOut b = eval::leaveOneOut(rows, eval::SweepScore::GroundF1B);
    ASSERT_EQ(b.folds.size(), 2u);
    EXPECT_EQ(b.folds[0].frame, "00/0");
    EXPECT_EQ(b.folds[1].frame, "00/2");
    // Without frame 0: frame 2 alone, value 0 (99): scored 97 on frame 0. Without frame 2:
    // value 1 (99): 95 on frame 2.
    EXPECT_DOUBLE_EQ(b.held_out_mean, (97.0 + 95.0) / 2);
    EXPECT_DOUBLE_EQ(b.in_sample_mean, 98.0);
    // Coverage: frames 0 and 1 have instances, frame 2 none.
    const eval::LeaveOneOut coverage = eval::leaveOneOut(rows, eval::SweepScore::Coverage);
    ASSERT_EQ(coverage.folds.size(), 2u);
    EXPECT_EQ(coverage.folds[1].frame, "00/1");
    EXPECT_DOUBLE_EQ(coverage.held_out_mean, 0.9);
    // Purity is a mean over the instances in a cluster: with frame 1's instances all unclustered
    // (no purity at either value) and frame 2 without instances, only frame 0 has a purity, while
    // coverage keeps frames 0 and 1 (an unclustered instance covers 0, a true score).
    for (auto& value : rows) {
        value[0].clustered = 3, value[0].purity = 0.95;
        value[1].clustered = 0, value[1].purity = 0.0;
    }
    EXPECT_EQ(eval::scoredFrames(rows, eval::SweepScore::Purity), (std::vector<std::size_t>{0}));
    EXPECT_EQ(eval::scoredFrames(rows, eval::SweepScore::Coverage),
              (std::vector<std::size_t>{0, 1}));
    // One frame with a score is no leave-one-out.
    for (auto& value : rows) value[0].ground[1].points = 0;
    EXPECT_THROW(eval::leaveOneOut(rows, eval::SweepScore::GroundF1B), std::invalid_argument);
}

// A method that never clustered (travel-eval sweep --method tgs --loo-score coverage) has no
// coverage or purity to choose on: an error, not folds of zeros choosing the first value.
TEST(LeaveOneOut, CoverageOrPurityOfAMethodThatNeverClusteredIsAnError) {
    std::vector<std::vector<eval::FrameRow>> rows(2, std::vector<eval::FrameRow>(2));
    for (auto& value : rows)
        for (eval::FrameRow& row : value) {
            row.ground[1].f1 = 98.0, row.ground[1].points = 1000;
            row.instances = 1;  // objects false
        }
    for (const eval::SweepScore score : {eval::SweepScore::Coverage, eval::SweepScore::Purity}) {
        try {
            eval::leaveOneOut(rows, score);
            FAIL() << "no error for " << eval::sweepScoreName(score);
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find("no frame was clustered"), std::string::npos)
                << e.what();
        }
    }
    EXPECT_NO_THROW(eval::leaveOneOut(rows, eval::SweepScore::GroundF1B));
    rows[1][0].objects = true;  // clustered at one value: scored (the others' 0 is honest)
    EXPECT_NO_THROW(eval::leaveOneOut(rows, eval::SweepScore::Coverage));
}

// travel-eval report on frames whose labels hold no ground truth (all unlabeled): no value ('-')
// rather than P / R / F1 of 0.00, and a line saying how many frames were scored.
TEST(ReportMarkdown, AProtocolWithNoScoredFrameHasNoValues) {
    std::vector<eval::MethodRun> runs(1);
    runs[0].method = "tgs";  // summary of no scored frame: every MeanStd has n = 0
    const std::vector<eval::FrameRef> frames = {{"s.bin", "s.label", "00/000000"}};
    const std::string md = eval::reportMarkdown(runs, frames, "preset none", 2);
    EXPECT_NE(md.find("logical CPUs, 2 worker threads (each frame on one);"), std::string::npos)
        << md;
    EXPECT_NE(md.find("| tgs | - | - | - | - | - | - | - |"), std::string::npos) << md;
    EXPECT_EQ(md.find("0.00"), std::string::npos) << md;
    EXPECT_NE(md.find("Scored frames (of 1): tgs 0"), std::string::npos) << md;
    // The sweep's CSV: empty cells, as frames.csv.
    std::ostringstream csv;
    eval::writeSweepCsv(csv, {"tgf_resolution", {"4"}}, {runs[0].summary}, 1);
    EXPECT_NE(csv.str().find("\n4,1,,,,,,,,,,,0,0\n"), std::string::npos) << csv.str();
}

}  // namespace
}  // namespace travel::eval
