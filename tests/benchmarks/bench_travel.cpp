// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// TRAVEL benchmarks, single-threaded, per sensor. Sensors ("cases"):
//   KITTI        SemanticKITTI seq 00 frames 0-2, HDL-64E, preset hdl64 (../shared/data)
//   OS128        shared/data/ouster128/000000.bin, 128 beams, preset os128 (../shared/data)
//   HDL32        shared/data/nuscenes/hdl32_000000.bin, preset hdl32 (../shared/data)
//   Synthetic    synthetic HDL-64E frame of the mixed scene (always available)
//   Synthetic128 synthetic OS1-128 frame (1875 columns) of the mixed scene, preset os128 with
//                the sensor 1.73 m above the ground (always available)
// Benchmarks, for each case C:
//   BM_Ground_C     ground segmentation (TGS) only, warm buffers
//   BM_Travel_C     TGS + object segmentation (AOS), the whole pipeline, warm buffers
//   BM_Objects_C    the AOS stages' own time inside the whole pipeline (manual timing)
//   BM_FirstFrame_C the first process() of a freshly built Pipeline (manual timing: the
//                   thread's CPU time, page faults included; construction and
//                   Pipeline::reserve(Result&) in the counter `build_ms`, wall time `wall_ms`).
//                   Inside one process the allocator reuses memory freed by the previous iteration,
//                   so this is a lower bound of a new process's first frame (travel-kitti on one
//                   file measures that)
//   BM_Stage_C/<stage> each stage alone on the state the previous stages leave
//   BM_Tracking_KITTI   travel::Tracker::update on the clusters of KITTI frames 0, 1, 2 in turn
//                   (poses from registering the frames' non-ground points, computed once
//                   outside the timing; a reset before frame 0), i.e. the tracker alone, with the
//                   clusters' point samples (ClusterSamples::build) and the tracks' shape
//                   alignment (docs/tracking.md); BM_Tracking_KITTI_CentroidOnly without them
//                   (the tracker before the alignment)
//   BM_Registration_KITTI the ego-motion estimate of travel-kitti --track without poses:
//                   ScanRegistration of frame 1's non-ground points to frame 0's
//   BM_ReadScan_KITTI / _PCD / _Synthetic  travel::readScan of one file into a reused cloud
//                   (the bytes from the page cache, then decoded): SemanticKITTI 00 frame 0,
//                   kitti_raw_pcd frame 0 (binary PCD, x y z intensity), the Synthetic case
//                   written as a KITTI .bin to a temporary file (always available)
// (KITTI cases take the frame as argument: BM_Ground_KITTI/0..2; stages use frame 0.)
// Cases whose data is missing report an error and are skipped.
// Run: build/tests/benchmarks/bench_travel --benchmark_repetitions=10
//        --benchmark_report_aggregates_only=true --benchmark_out=bench_travel.json
// docs/performance.md has the figures and the per-stage table.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "travel/GroundLabelling.hpp"
#include "travel/NodeFitting.hpp"
#include "travel/ParamsIO.hpp"
#include "travel/Pipeline.hpp"
#include "travel/RunClustering.hpp"
#include "travel/TerrainModelFitting.hpp"
#include "travel/TraversableGraphSearch.hpp"
#include "travel/eval/KittiIO.hpp"
#include "travel/io/ScanIO.hpp"
#include "travel/sim/Scenes.hpp"
#include "travel/sim/SyntheticLidar.hpp"
#include "travel/tracking/FrameTracker.hpp"

namespace fs = std::filesystem;
using namespace travel;

namespace {

// One sensor case: its parameters and a frame (empty `cloud` = data missing).
struct Case {
    const char* name;
    Params params;
    PointCloud cloud;
};

bool readShared(const std::string& relative, ScanFormat format, PointCloud& cloud) {
    const fs::path path = fs::path(TRAVEL_DATA_DIR) / relative;
    if (!fs::exists(path)) return false;
    readScan(path.string(), cloud, format);
    return true;
}

PointCloud kittiFrame(int index) {
    char name[64];
    std::snprintf(name, sizeof name, "semantickitti/sequences/00/velodyne/%06d.bin", index);
    PointCloud cloud;
    readShared(name, ScanFormat::KittiBin, cloud);
    return cloud;
}

// A synthetic frame of the mixed scene (ramp, kerb, bumps, car, pole, wall), sensor 1.73 m up.
PointCloud syntheticFrame(sim::LidarModel lidar) {
    const sim::Scene scene = sim::mixed();
    lidar.range_noise_sigma = 0.02;
    return sim::scan(scene, lidar, sim::sensorPoseAt(scene, 0, 0, 1.73, 0, 0, 0)).cloud;
}

enum CaseId { kKitti0, kKitti1, kKitti2, kOs128, kHdl32, kSynthetic, kSynthetic128, kNumCases };

// Loaded once, on first use (the benchmarks of a filtered run load only what they need).
const Case& getCase(CaseId id) {
    static std::unique_ptr<Case> cases[kNumCases];
    if (!cases[id]) {
        auto c = std::make_unique<Case>();
        switch (id) {
            case kKitti0:
            case kKitti1:
            case kKitti2:
                *c = Case{"KITTI", loadPreset("hdl64"), kittiFrame(id - kKitti0)};
                break;
            case kOs128:
                c->name = "OS128";
                c->params = loadPreset("os128");
                readShared("ouster128/000000.bin", ScanFormat::KittiBin, c->cloud);
                break;
            case kHdl32:
                c->name = "HDL32";
                c->params = loadPreset("hdl32");
                readShared("nuscenes/hdl32_000000.bin", ScanFormat::NuScenesBin, c->cloud);
                break;
            case kSynthetic:
                // Default parameters (= HDL-64E on KITTI), as since the first benchmarks.
                *c = Case{"Synthetic", Params{}, syntheticFrame(sim::LidarModel::hdl64())};
                break;
            case kSynthetic128:
                c->name = "Synthetic128";
                c->params = loadPreset("os128");
                c->params.sensor_height = 1.73;
                c->cloud = syntheticFrame(sim::LidarModel::os128(1875));
                break;
            default:
                break;
        }
        cases[id] = std::move(c);
    }
    return *cases[id];
}

bool haveData(benchmark::State& state, const Case& c) {
    if (!c.cloud.empty()) return true;
    state.SkipWithError((std::string(c.name) + ": data not found (../shared/data)").c_str());
    return false;
}

// Warm buffers, as on a running vehicle, and the mount settled: a mount that finds no ground
// (OS128: its origin is at ground level) is tried on up to 10 frames, each paying the estimate.
void warmUp(Pipeline& pipeline, const PointCloud& cloud, Result& result) {
    do {
        pipeline.process(cloud, {}, result);
    } while (!pipeline.mountSettled());
}

void runWarm(benchmark::State& state, CaseId id, bool objects) {
    const Case& c = getCase(id);
    if (!haveData(state, c)) return;
    Params params = c.params;
    params.cluster_objects = objects;
    Pipeline pipeline(params);
    Result result;
    warmUp(pipeline, c.cloud, result);
    for (auto _ : state) {
        pipeline.process(c.cloud, {}, result);
        benchmark::DoNotOptimize(result.labels.data());
    }
    state.counters["points"] = static_cast<double>(c.cloud.size());
    state.counters["ground"] = static_cast<double>(result.count(PointClass::Ground));
    state.counters["clusters"] = static_cast<double>(result.clusters.size());
}

// The object stage alone, inside the whole pipeline (same cache state as in use): each
// iteration runs ground + objects and reports the objects' own time (manual timing).
void runObjects(benchmark::State& state, CaseId id) {
    const Case& c = getCase(id);
    if (!haveData(state, c)) return;
    Pipeline pipeline(c.params);
    Result result;
    warmUp(pipeline, c.cloud, result);
    for (auto _ : state) {
        pipeline.process(c.cloud, {}, result);
        state.SetIterationTime(result.timings.objects_total / 1000.0);
    }
    state.counters["clusters"] = static_cast<double>(result.clusters.size());
}

// CPU time of the calling thread [s], page faults included (kernel time on its behalf): on a
// shared machine wall-clock time mostly measures the other processes.
double threadCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The first frame of a new Pipeline (manual timing: the thread's CPU time in process()); the
// counters give the construction + Pipeline::reserve(Result&) (`build_ms`, CPU) and the first
// frame's wall-clock time (`wall_ms`).
void runFirstFrame(benchmark::State& state, CaseId id) {
    using Clock = std::chrono::steady_clock;
    const Case& c = getCase(id);
    if (!haveData(state, c)) return;
    double build_ms = 0, wall_ms = 0;
    for (auto _ : state) {
        const double t0 = threadCpuSeconds();
        auto pipeline = std::make_unique<Pipeline>(c.params);
        Result result;
        pipeline->reserve(result);
        const double t1 = threadCpuSeconds();
        const Clock::time_point w1 = Clock::now();
        pipeline->process(c.cloud, {}, result);
        const Clock::time_point w2 = Clock::now();
        const double t2 = threadCpuSeconds();
        benchmark::DoNotOptimize(result.labels.data());
        state.SetIterationTime(t2 - t1);
        build_ms += 1e3 * (t1 - t0);
        wall_ms += std::chrono::duration<double, std::milli>(w2 - w1).count();
    }
    const double n = static_cast<double>(std::max<int64_t>(state.iterations(), 1));
    state.counters["build_ms"] = build_ms / n;
    state.counters["wall_ms"] = wall_ms / n;
}

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
    kClusters,
    kNumStages
};
constexpr const char* kStageNames[kNumStages] = {
    "preprocess", "embedding",   "node_fitting", "graph_search", "ttmf",
    "labelling",  "range_image", "horizontal",   "vertical",     "clusters"};

void runStage(benchmark::State& state, CaseId id, Stage stage) {
    const Case& c = getCase(id);
    if (!haveData(state, c)) return;
    const PointCloud& cloud = c.cloud;
    // The parameters the Pipeline uses (e.g. its seed search radius reaching the first ring).
    const Params params = Pipeline(c.params).params();
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
    preprocess(cloud, params, {}, aligned, &field.geometry());
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
                preprocess(cloud, params, {}, aligned, &field.geometry());
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
            default:
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

// Segmented KITTI frames 0-2 (clusters, labels), once.
struct SegmentedKitti {
    std::vector<PointCloud> clouds;
    std::vector<Result> results;
    Eigen::Matrix3f rotation = Eigen::Matrix3f::Identity();
    /// The aligned frame of each frame in frame 0's sensor frame, from registering each frame's
    /// non-ground points to the previous frame's (the ego-motion travel-kitti --track uses).
    std::vector<Eigen::Isometry3d> world_T_aligned;
};

/// Frame f's non-ground points within the tracker's registration range (sensor frame).
std::vector<Eigen::Vector3d> nonGroundPoints(const SegmentedKitti& kitti, std::size_t f) {
    std::vector<Eigen::Vector3d> points;
    for (std::size_t i = 0; i < kitti.clouds[f].size(); ++i) {
        const Eigen::Vector3d p(kitti.clouds[f].x[i], kitti.clouds[f].y[i], kitti.clouds[f].z[i]);
        if (kitti.results[f].labels[i] == PointClass::NonGround &&
            p.head<2>().norm() <= FrameTracker::registration_range)
            points.push_back(p);
    }
    return points;
}

const SegmentedKitti& segmentedKitti() {
    static const SegmentedKitti s = [] {
        SegmentedKitti out;
        const Case& c = getCase(kKitti0);
        if (c.cloud.size() == 0) return out;
        Pipeline pipeline(c.params);
        for (int f = 0; f < 3; ++f) {
            out.clouds.push_back(getCase(static_cast<CaseId>(kKitti0 + f)).cloud);
            Result result;
            pipeline.process(out.clouds.back(), {}, result);
            out.results.push_back(std::move(result));
        }
        out.rotation = pipeline.aligned().rotation;
        ScanRegistration registration(RegistrationParams::nonGroundOdometry());
        Eigen::Isometry3d world_T_sensor = Eigen::Isometry3d::Identity();
        Eigen::Isometry3d sensor_T_aligned = Eigen::Isometry3d::Identity();
        sensor_T_aligned.linear() = out.rotation.cast<double>().transpose();
        for (std::size_t f = 0; f < out.clouds.size(); ++f) {
            if (f > 0) {
                registration.setTarget(nonGroundPoints(out, f - 1));
                // target_T_source: frame f's sensor pose in frame f - 1's.
                world_T_sensor = world_T_sensor * registration.align(nonGroundPoints(out, f),
                                                                     Eigen::Isometry3d::Identity());
            }
            out.world_T_aligned.push_back(world_T_sensor * sensor_T_aligned);
        }
        return out;
    }();
    return s;
}

void runTracking(benchmark::State& state, bool shape) {
    const SegmentedKitti& kitti = segmentedKitti();
    if (kitti.results.empty()) return state.SkipWithError("KITTI frames not found");
    Tracker tracker;
    ClusterSamples samples;
    std::vector<ClusterSummary> clusters;
    std::size_t k = 0;
    for (auto _ : state) {
        const std::size_t f = k % 3;
        state.PauseTiming();
        if (f == 0) tracker.reset();
        clusters = kitti.results[f].clusters;
        state.ResumeTiming();
        if (shape)
            samples.build(kitti.clouds[f], kitti.results[f].cluster_id, kitti.rotation, clusters);
        tracker.update(0.1 * double(k++), kitti.world_T_aligned[f], clusters,
                       shape ? &samples : nullptr);
        benchmark::DoNotOptimize(clusters.data());
    }
    state.counters["clusters"] = static_cast<double>(kitti.results[0].clusters.size());
}

void runRegistration(benchmark::State& state) {
    const SegmentedKitti& kitti = segmentedKitti();
    if (kitti.results.empty()) return state.SkipWithError("KITTI frames not found");
    const std::vector<Eigen::Vector3d> points[2] = {nonGroundPoints(kitti, 0),
                                                    nonGroundPoints(kitti, 1)};
    ScanRegistration registration(RegistrationParams::nonGroundOdometry());
    for (auto _ : state) {
        registration.setTarget(points[0]);
        benchmark::DoNotOptimize(registration.align(points[1], Eigen::Isometry3d::Identity()));
    }
    state.counters["points"] = static_cast<double>(points[1].size());
}

// travel::readScan of one file, the cloud reused (as the apps' workers do).
void runReadScan(benchmark::State& state, const std::string& path) {
    if (!fs::exists(path)) {
        state.SkipWithError((path + ": not found (../shared/data)").c_str());
        return;
    }
    PointCloud cloud;
    for (auto _ : state) {
        readScan(path, cloud);
        benchmark::DoNotOptimize(cloud.x.data());
    }
    state.counters["points"] = static_cast<double>(cloud.size());
}

void registerAll() {
    using benchmark::RegisterBenchmark;
    struct Named {
        CaseId id;
        const char* name;
    };
    // Whole-pipeline benchmarks: the three KITTI frames as /0../2, then the other sensors.
    for (const char* what : {"Ground", "Travel", "Objects"}) {
        const std::string kind = what;
        auto add = [&](const std::string& name, CaseId id) {
            benchmark::internal::Benchmark* b;
            if (kind == "Objects") {
                b = RegisterBenchmark(name.c_str(), [id](benchmark::State& s) {
                        runObjects(s, id);
                    })->UseManualTime();
            } else {
                const bool objects = kind == "Travel";
                b = RegisterBenchmark(
                    name.c_str(), [id, objects](benchmark::State& s) { runWarm(s, id, objects); });
            }
            b->Unit(benchmark::kMillisecond);
        };
        for (int f = 0; f < 3; ++f)
            add("BM_" + kind + "_KITTI/" + std::to_string(f), static_cast<CaseId>(kKitti0 + f));
        for (const Named& n :
             {Named{kOs128, "OS128"}, Named{kHdl32, "HDL32"}, Named{kSynthetic, "Synthetic"},
              Named{kSynthetic128, "Synthetic128"}})
            add("BM_" + kind + "_" + n.name, n.id);
    }
    const Named all[] = {{kKitti0, "KITTI"},
                         {kOs128, "OS128"},
                         {kHdl32, "HDL32"},
                         {kSynthetic, "Synthetic"},
                         {kSynthetic128, "Synthetic128"}};
    for (const Named& n : all)
        RegisterBenchmark(("BM_FirstFrame_" + std::string(n.name)).c_str(),
                          [id = n.id](benchmark::State& s) { runFirstFrame(s, id); })
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
    for (const Named& n : all)
        for (int stage = 0; stage < kNumStages; ++stage)
            RegisterBenchmark(
                ("BM_Stage_" + std::string(n.name) + "/" + kStageNames[stage]).c_str(),
                [id = n.id, stage](benchmark::State& s) {
                    runStage(s, id, static_cast<Stage>(stage));
                })
                ->Unit(benchmark::kMicrosecond);
    RegisterBenchmark("BM_Tracking_KITTI", runTracking, true)->Unit(benchmark::kMicrosecond);
    RegisterBenchmark("BM_Tracking_KITTI_CentroidOnly", runTracking, false)
        ->Unit(benchmark::kMicrosecond);
    RegisterBenchmark("BM_Registration_KITTI", runRegistration)->Unit(benchmark::kMillisecond);
    const fs::path data(TRAVEL_DATA_DIR);
    RegisterBenchmark("BM_ReadScan_KITTI", runReadScan,
                      (data / "semantickitti/sequences/00/velodyne/000000.bin").string())
        ->Unit(benchmark::kMicrosecond);
    RegisterBenchmark("BM_ReadScan_PCD", runReadScan,
                      (data / "kitti_raw_pcd/0000000000.pcd").string())
        ->Unit(benchmark::kMicrosecond);
    RegisterBenchmark("BM_ReadScan_Synthetic", [](benchmark::State& state) {
        const fs::path path = fs::temp_directory_path() / "travel_bench_synthetic.bin";
        writeKittiBin(path.string(), getCase(kSynthetic).cloud);
        runReadScan(state, path.string());
        fs::remove(path);
    })->Unit(benchmark::kMicrosecond);
}

}  // namespace

int main(int argc, char** argv) {
    registerAll();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
