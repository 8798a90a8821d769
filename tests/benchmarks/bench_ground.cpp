// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Ground-segmentation benchmarks, single-threaded:
//   BM_Ground_KITTI/<frame>   whole TGS on SemanticKITTI seq 00 frames 0-2 (when ../shared/data
//                             is present; otherwise the benchmark reports an error and skips)
//   BM_Stage_KITTI_<stage>    each stage alone on frame 000000
//   BM_Ground_Synthetic       whole TGS on a synthetic HDL-64E frame (always available)
// Run: build/tests/benchmarks/bench_ground --benchmark_repetitions=10
//        --benchmark_report_aggregates_only=true --benchmark_out=bench_ground.json
#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "travel/GroundLabelling.hpp"
#include "travel/KittiIO.hpp"
#include "travel/NodeFitting.hpp"
#include "travel/ParamsIO.hpp"
#include "travel/Pipeline.hpp"
#include "travel/TerrainModelFitting.hpp"
#include "travel/TraversableGraphSearch.hpp"
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
    readKittiBin(path.string(), cloud);
    return true;
}

void BM_Ground_KITTI(benchmark::State& state) {
    PointCloud cloud;
    if (!loadKittiFrame(static_cast<int>(state.range(0)), cloud)) {
        state.SkipWithError("SemanticKITTI frames not found (../shared/data)");
        return;
    }
    Pipeline pipeline(loadPreset("hdl64"));
    Result result;
    pipeline.process(cloud, {}, result);  // warm the buffers, as on a running vehicle
    for (auto _ : state) {
        pipeline.process(cloud, {}, result);
        benchmark::DoNotOptimize(result.labels.data());
    }
    state.counters["points"] = static_cast<double>(cloud.size());
    state.counters["ground"] = static_cast<double>(result.count(PointClass::Ground));
}
BENCHMARK(BM_Ground_KITTI)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

// Each stage alone, on the state the previous stages leave.
enum Stage { kPreprocess, kEmbedding, kNodeFitting, kGraphSearch, kTtmf, kLabelling };

void BM_Stage_KITTI(benchmark::State& state, Stage stage) {
    PointCloud cloud;
    if (!loadKittiFrame(0, cloud)) {
        state.SkipWithError("SemanticKITTI frames not found (../shared/data)");
        return;
    }
    const Params params = loadPreset("hdl64");
    AlignedCloud aligned;
    TriGridField field;
    field.configure(params);
    TerrainModel model;
    TraversableGraphSearch search;
    TerrainModelFitting ttmf;
    std::vector<PointClass> labels;
    preprocess(cloud, params, {}, aligned);
    field.embed(aligned, model);
    fitNodes(field, params, model);
    search.run(field, params, model);
    ttmf.run(field, params, model);
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

void BM_Ground_Synthetic(benchmark::State& state) {
    const sim::Scene scene = sim::mixed();
    sim::LidarModel lidar = sim::LidarModel::hdl64();
    lidar.range_noise_sigma = 0.02;
    const sim::Scan scan = sim::scan(scene, lidar, sim::sensorPoseAt(scene, 0, 0, 1.73, 0, 0, 0));
    Pipeline pipeline(Params{});
    Result result;
    for (auto _ : state) {
        pipeline.process(scan.cloud, {}, result);
        benchmark::DoNotOptimize(result.labels.data());
    }
    state.counters["points"] = static_cast<double>(scan.cloud.size());
}
BENCHMARK(BM_Ground_Synthetic)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
