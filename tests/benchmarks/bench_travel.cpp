// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// TRAVEL benchmarks, single-threaded:
//   BM_Ground_KITTI/<frame>   ground segmentation (TGS) only, SemanticKITTI seq 00 frames 0-2
//                             (when ../shared/data is present; otherwise reports an error)
//   BM_Travel_KITTI/<frame>   TGS + object segmentation (AOS), the whole pipeline
//   BM_Objects_KITTI/<frame>  the AOS stages' own time inside the whole pipeline
//   BM_Stage_KITTI/<stage>    each stage alone on frame 000000
//   BM_Stage_Synthetic/<stage> each stage alone on a synthetic HDL-64E frame
//   BM_Ground_Synthetic, BM_Travel_Synthetic: a synthetic HDL-64E frame (always available)
// Run: build/tests/benchmarks/bench_travel --benchmark_repetitions=10
//        --benchmark_report_aggregates_only=true --benchmark_out=bench_travel.json
#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "travel/GroundLabelling.hpp"
#include "travel/NodeFitting.hpp"
#include "travel/ParamsIO.hpp"
#include "travel/Pipeline.hpp"
#include "travel/RunClustering.hpp"
#include "travel/TerrainModelFitting.hpp"
#include "travel/TraversableGraphSearch.hpp"
#include "travel/eval/KittiIO.hpp"
#include "travel/sim/Scenes.hpp"
#include "travel/sim/SyntheticLidar.hpp"

namespace fs = std::filesystem;
using namespace travel;

namespace {

bool loadKittiFrame(int index, PointCloud& cloud) {
    char name[32];
    std::snprintf(name, sizeof name, "%06d.bin", index);
    const fs::path path = fs::path(TRAVEL_DATA_DIR) / "semantickitti/sequences/00/velodyne" / name;
    if (!fs::exists(path)) return false;
    readScan(path.string(), cloud, ScanFormat::KittiBin);
    return true;
}

void runKitti(benchmark::State& state, bool objects) {
    PointCloud cloud;
    if (!loadKittiFrame(static_cast<int>(state.range(0)), cloud)) {
        state.SkipWithError("SemanticKITTI frames not found (../shared/data)");
        return;
    }
    Params params = loadPreset("hdl64");
    params.cluster_objects = objects;
    Pipeline pipeline(params);
    Result result;
    pipeline.process(cloud, {}, result);  // warm the buffers, as on a running vehicle
    for (auto _ : state) {
        pipeline.process(cloud, {}, result);
        benchmark::DoNotOptimize(result.labels.data());
    }
    state.counters["points"] = static_cast<double>(cloud.size());
    state.counters["ground"] = static_cast<double>(result.count(PointClass::Ground));
    state.counters["clusters"] = static_cast<double>(result.clusters.size());
}
void BM_Ground_KITTI(benchmark::State& state) {
    runKitti(state, false);
}
void BM_Travel_KITTI(benchmark::State& state) {
    runKitti(state, true);
}
BENCHMARK(BM_Ground_KITTI)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Travel_KITTI)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

// The object stage alone, inside the whole pipeline (same cache state as in use): each
// iteration runs ground + objects and reports the objects' own time (manual timing).
void BM_Objects_KITTI(benchmark::State& state) {
    PointCloud cloud;
    if (!loadKittiFrame(static_cast<int>(state.range(0)), cloud)) {
        state.SkipWithError("SemanticKITTI frames not found (../shared/data)");
        return;
    }
    Pipeline pipeline(loadPreset("hdl64"));
    Result result;
    pipeline.process(cloud, {}, result);
    for (auto _ : state) {
        pipeline.process(cloud, {}, result);
        state.SetIterationTime(result.timings.objects_total / 1000.0);
    }
    state.counters["clusters"] = static_cast<double>(result.clusters.size());
}
BENCHMARK(BM_Objects_KITTI)->DenseRange(0, 2)->UseManualTime()->Unit(benchmark::kMillisecond);

// Each stage alone, on the state the previous stages leave.
enum Stage {
    kPreprocess,
    kEmbedding,
    kNodeFitting,
    kGraphSearch,
    kTtmf,
    kLabelling,
    kRangeImage,
    kHorizontal,
    kVertical,
    kClusters
};

// A synthetic HDL-64E frame of the mixed scene (ramp, kerb, bumps, car, pole, wall; ~118k
// points), available without ../shared/data.
const PointCloud& syntheticFrame() {
    static const PointCloud cloud = [] {
        const sim::Scene scene = sim::mixed();
        sim::LidarModel lidar = sim::LidarModel::hdl64();
        lidar.range_noise_sigma = 0.02;
        return sim::scan(scene, lidar, sim::sensorPoseAt(scene, 0, 0, 1.73, 0, 0, 0)).cloud;
    }();
    return cloud;
}

void runStage(benchmark::State& state, const PointCloud& cloud, Stage stage);

void BM_Stage_KITTI(benchmark::State& state, Stage stage) {
    PointCloud cloud;
    if (!loadKittiFrame(0, cloud)) {
        state.SkipWithError("SemanticKITTI frames not found (../shared/data)");
        return;
    }
    runStage(state, cloud, stage);
}

void BM_Stage_Synthetic(benchmark::State& state, Stage stage) {
    runStage(state, syntheticFrame(), stage);
}

void runStage(benchmark::State& state, const PointCloud& cloud, Stage stage) {
    const Params params = loadPreset("hdl64");
    AlignedCloud aligned;
    TriGridField field;
    field.configure(params);
    TerrainModel model;
    TraversableGraphSearch search;
    TerrainModelFitting ttmf;
    std::vector<PointClass> labels;
    RangeImage image;
    RunClustering clustering;
    std::vector<uint32_t> cluster_id(cloud.size(), 0);
    std::vector<ClusterSummary> clusters;
    preprocess(cloud, params, {}, aligned);
    field.embed(aligned, model);
    fitNodes(field, params, model);
    search.run(field, params, model);
    ttmf.run(field, params, model);
    labelPoints(field, aligned, params, model, labels);
    image.build(cloud, aligned.valid, params);
    clustering.horizontal(aligned, image, labels, params);
    clustering.vertical(params);
    for (auto _ : state) {
        switch (stage) {
            case kPreprocess:
                preprocess(cloud, params, {}, aligned);
                break;
            case kEmbedding:
                field.embed(aligned, model);
                break;
            case kNodeFitting:
                fitNodes(field, params, model);
                break;
            case kGraphSearch:
                search.run(field, params, model);
                break;
            case kTtmf:
                ttmf.run(field, params, model);
                break;
            case kLabelling:
                labelPoints(field, aligned, params, model, labels);
                break;
            case kRangeImage:
                image.build(cloud, aligned.valid, params);
                break;
            case kHorizontal:
                clustering.horizontal(aligned, image, labels, params);
                break;
            case kVertical:
                // Vertical merges change the union-find: rebuild the runs outside the timing.
                state.PauseTiming();
                clustering.horizontal(aligned, image, labels, params);
                state.ResumeTiming();
                clustering.vertical(params);
                break;
            case kClusters:
                clustering.assignIds(params, cluster_id);
                clustering.summarize(field, model, clusters);
                break;
        }
        benchmark::ClobberMemory();
        // Embedding resets the model: refit so the later stages' inputs stay meaningful.
        if (stage == kEmbedding) {
            state.PauseTiming();
            fitNodes(field, params, model);
            search.run(field, params, model);
            ttmf.run(field, params, model);
            state.ResumeTiming();
        }
    }
}
BENCHMARK_CAPTURE(BM_Stage_KITTI, preprocess, kPreprocess)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Stage_KITTI, embedding, kEmbedding)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Stage_KITTI, node_fitting, kNodeFitting)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Stage_KITTI, graph_search, kGraphSearch)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Stage_KITTI, ttmf, kTtmf)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Stage_KITTI, labelling, kLabelling)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Stage_KITTI, range_image, kRangeImage)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Stage_KITTI, horizontal, kHorizontal)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Stage_KITTI, vertical, kVertical)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Stage_KITTI, clusters, kClusters)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Stage_Synthetic, preprocess, kPreprocess)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Stage_Synthetic, embedding, kEmbedding)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Stage_Synthetic, node_fitting, kNodeFitting)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Stage_Synthetic, graph_search, kGraphSearch)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Stage_Synthetic, ttmf, kTtmf)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Stage_Synthetic, labelling, kLabelling)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Stage_Synthetic, range_image, kRangeImage)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Stage_Synthetic, horizontal, kHorizontal)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Stage_Synthetic, vertical, kVertical)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Stage_Synthetic, clusters, kClusters)->Unit(benchmark::kMicrosecond);

void runSynthetic(benchmark::State& state, bool objects) {
    const PointCloud& cloud = syntheticFrame();
    Params params;
    params.cluster_objects = objects;
    Pipeline pipeline(params);
    Result result;
    for (auto _ : state) {
        pipeline.process(cloud, {}, result);
        benchmark::DoNotOptimize(result.labels.data());
    }
    state.counters["points"] = static_cast<double>(cloud.size());
}
void BM_Ground_Synthetic(benchmark::State& state) {
    runSynthetic(state, false);
}
void BM_Travel_Synthetic(benchmark::State& state) {
    runSynthetic(state, true);
}
BENCHMARK(BM_Ground_Synthetic)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Travel_Synthetic)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
