// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Robustness: one test per bad input of the README's "Input contract", resource limits (a
// 2,000,000-point cloud, a 1 km grid) and thread safety (one Pipeline per thread). The resource
// tests print time and peak RSS but assert neither.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <memory>
#include <new>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "OrderedWork.hpp"  // apps/: -j N of the batch apps
#include "SceneMetrics.hpp"
#include "travel/Errors.hpp"
#include "travel/Params.hpp"
#include "travel/ParamsIO.hpp"
#include "travel/Pipeline.hpp"
#include "travel/sim/Scenes.hpp"
#include "travel/sim/SyntheticLidar.hpp"

// The global operator new, counting its calls on a thread while that thread asks for it
// (Robustness.NoAllocationOnceEveryFrameWasSeen): every form that std::vector, std::string and
// the standard algorithms' buffers use (plain, array, nothrow; ASan replaces each on its own),
// on malloc and free, which the sanitizers still intercept.
namespace {
thread_local bool t_count_allocations = false;
thread_local std::size_t t_allocations = 0;
void* countedNew(std::size_t size) noexcept {
    if (t_count_allocations) ++t_allocations;
    return std::malloc(size ? size : 1);
}
void* countedNewOrThrow(std::size_t size) {
    if (void* p = countedNew(size)) return p;
    throw std::bad_alloc();
}
}  // namespace

void* operator new(std::size_t size) {
    return countedNewOrThrow(size);
}
void* operator new[](std::size_t size) {
    return countedNewOrThrow(size);
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    return countedNew(size);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
    return countedNew(size);
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete[](void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
    std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
    std::free(p);
}

namespace travel {
namespace {

constexpr double kSensorHeight = 1.73;
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

Params testParams() {
    Params params;
    params.sensor_height = kSensorHeight;
    return params;
}

sim::LidarModel testLidar() {
    sim::LidarModel model = sim::LidarModel::hdl64();
    model.range_noise_sigma = 0.01;
    model.seed = 7;
    model.max_range = Params{}.max_range;
    return model;
}

sim::Scan urbanScan() {
    const sim::Scene scene = sim::urbanObjects();
    return sim::scan(scene, testLidar(), sim::sensorPoseAt(scene, 0, 0, kSensorHeight, 0, 0, 0));
}

Result run(const PointCloud& cloud, const Params& params = testParams(),
           const FrameInput& input = {}) {
    Pipeline pipeline(params);
    Result result;
    pipeline.process(cloud, input, result);
    return result;
}

/// Every input point has exactly one defined label, the counts add up, cluster ids refer to
/// clusters of non-ground points and no cluster is larger than the input.
void expectConsistent(const PointCloud& cloud, const Result& result) {
    const std::size_t n = cloud.size();
    ASSERT_EQ(result.labels.size(), n);
    ASSERT_EQ(result.cluster_id.size(), n);
    std::array<std::size_t, 4> counts{};
    std::vector<std::size_t> cluster_sizes(result.clusters.size() + 1, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const int c = static_cast<int>(result.labels[i]);
        ASSERT_GE(c, 0);
        ASSERT_LE(c, 3) << "point " << i;
        ++counts[c];
        const uint32_t id = result.cluster_id[i];
        ASSERT_LE(id, result.clusters.size()) << "point " << i;
        if (id != 0) {
            EXPECT_EQ(result.labels[i], PointClass::NonGround) << "clustered point " << i;
            ++cluster_sizes[id];
        }
    }
    EXPECT_EQ(counts, result.class_counts);
    for (std::size_t k = 0; k < result.clusters.size(); ++k) {
        EXPECT_EQ(result.clusters[k].id, k + 1);
        EXPECT_EQ(result.clusters[k].num_points, cluster_sizes[k + 1]);
        EXPECT_LE(result.clusters[k].num_points, n);
    }
}

/// Peak resident set size of this process [MB] (Linux: ru_maxrss is in kB).
double peakRssMb() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

/// Inserts points made by `bad()` before about one point in `every` of `clean` (seeded), with
/// ring and time kept aligned. origin[k] = index in `clean`, or -1 for an inserted point.
PointCloud insertBadPoints(const PointCloud& clean, int every,
                           const std::function<void(std::mt19937&, float*)>& bad,
                           std::vector<int>& origin) {
    std::mt19937 rng(42);
    PointCloud dirty;
    const bool ring = clean.hasRing(), time = clean.hasTime();
    origin.clear();
    for (std::size_t i = 0; i < clean.size(); ++i) {
        if (rng() % every == 0) {
            float p[3];
            bad(rng, p);
            dirty.push_back(p[0], p[1], p[2], 0.f);
            if (ring) dirty.ring.push_back(static_cast<uint16_t>(rng() % 64));
            if (time) dirty.time.push_back(clean.time[i]);
            origin.push_back(-1);
        }
        dirty.push_back(clean.x[i], clean.y[i], clean.z[i], clean.intensity[i]);
        if (ring) dirty.ring.push_back(clean.ring[i]);
        if (time) dirty.time.push_back(clean.time[i]);
        origin.push_back(static_cast<int>(i));
    }
    return dirty;
}

/// The inserted points are Invalid with no cluster; every other point keeps its clean label and
/// cluster id.
void expectInsertedInvalidOthersUnchanged(const Result& clean, const Result& dirty,
                                          const std::vector<int>& origin) {
    ASSERT_EQ(dirty.labels.size(), origin.size());
    std::size_t inserted = 0, changed_label = 0, changed_cluster = 0;
    for (std::size_t k = 0; k < origin.size(); ++k) {
        if (origin[k] < 0) {
            ++inserted;
            EXPECT_EQ(dirty.labels[k], PointClass::Invalid) << "inserted point " << k;
            EXPECT_EQ(dirty.cluster_id[k], 0u);
            continue;
        }
        changed_label += dirty.labels[k] != clean.labels[origin[k]];
        changed_cluster += dirty.cluster_id[k] != clean.cluster_id[origin[k]];
    }
    EXPECT_GT(inserted, 0u);
    EXPECT_EQ(changed_label, 0u);
    EXPECT_EQ(changed_cluster, 0u);
    EXPECT_EQ(dirty.clusters.size(), clean.clusters.size());
}

// ---- Degenerate clouds ----

TEST(Robustness, EmptyCloud) {
    const PointCloud cloud;
    Result result;
    ASSERT_NO_THROW(result = run(cloud));
    expectConsistent(cloud, result);
    EXPECT_TRUE(result.labels.empty());
    EXPECT_TRUE(result.clusters.empty());
    EXPECT_EQ(result.terrain.seed_node, -1);
}

TEST(Robustness, OnePoint) {
    PointCloud cloud;
    cloud.push_back(5.f, 0.f, -static_cast<float>(kSensorHeight));
    const Result result = run(cloud);
    expectConsistent(cloud, result);
    EXPECT_EQ(result.labels[0], PointClass::NonGround);
    EXPECT_EQ(result.terrain.seed_node, -1);
}

TEST(Robustness, AllPointsInvalid) {
    PointCloud cloud;
    const float bad[][3] = {{kNaN, 0, 0},  {0, kNaN, -1}, {1, 2, kNaN},        {kInf, 0, 0},
                            {0, -kInf, 0}, {0, 0, kInf},  {-kInf, kInf, kNaN}, {0, 0, 0}};
    for (int copy = 0; copy < 100; ++copy)
        for (const auto& p : bad) cloud.push_back(p[0], p[1], p[2]);
    const Result result = run(cloud);
    expectConsistent(cloud, result);
    EXPECT_EQ(result.count(PointClass::Invalid), cloud.size());
    EXPECT_TRUE(result.clusters.empty());
    EXPECT_EQ(result.terrain.seed_node, -1);
}

// A frame without a valid point (empty, or every point NaN) is no error whatever the ring
// source, an explicit field or scan order included (they threw "no ring field" / "no point has
// an azimuth" there, stopping an app at a sensor dropout).
TEST(Robustness, NoValidPointUnderEveryRingSource) {
    PointCloud empty, all_nan;
    for (int k = 0; k < 50; ++k) all_nan.push_back(kNaN, 0.f, -1.f);
    all_nan.ring.assign(all_nan.size(), 3);
    for (const char* source : {"auto", "field", "scan_order", "table"}) {
        Params params = testParams();
        params.ring_source = source;
        for (const PointCloud* cloud : {&empty, &all_nan}) {
            Result result;
            ASSERT_NO_THROW(Pipeline(params).process(*cloud, {}, result)) << source;
            expectConsistent(*cloud, result);
            EXPECT_EQ(result.count(PointClass::Invalid), cloud->size()) << source;
            EXPECT_TRUE(result.clusters.empty()) << source;
        }
    }
}

TEST(Robustness, FivePercentNaNChangesNoOtherLabel) {
    const sim::Scan scan = urbanScan();
    const Result clean = run(scan.cloud);
    std::vector<int> origin;
    const PointCloud dirty = insertBadPoints(
        scan.cloud, 20,
        [](std::mt19937& rng, float* p) {
            p[0] = float(rng() % 40), p[1] = 1.f, p[2] = -1.f;
            p[rng() % 3] = kNaN;
        },
        origin);
    const Result result = run(dirty);
    expectConsistent(dirty, result);
    expectInsertedInvalidOthersUnchanged(clean, result, origin);
}

TEST(Robustness, CoordinatesOf1e30AreInvalid) {
    const sim::Scan scan = urbanScan();
    const Result clean = run(scan.cloud);
    std::vector<int> origin;
    const PointCloud dirty = insertBadPoints(
        scan.cloud, 20,
        [](std::mt19937& rng, float* p) {
            p[0] = 1.f, p[1] = 1.f, p[2] = -1.7f;
            const float sign = rng() % 2 ? 1.f : -1.f;
            p[rng() % 3] = sign * 1e30f;
        },
        origin);
    const Result result = run(dirty);
    expectConsistent(dirty, result);
    expectInsertedInvalidOthersUnchanged(clean, result, origin);

    // A cloud made only of them.
    PointCloud far;
    far.push_back(1e30f, 0, 0), far.push_back(0, -1e30f, 0), far.push_back(1e30f, 1e30f, 1e30f);
    const Result only = run(far);
    expectConsistent(far, only);
    EXPECT_EQ(only.count(PointClass::Invalid), far.size());
}

TEST(Robustness, TenThousandIdenticalPoints) {
    for (const float z : {-static_cast<float>(kSensorHeight), 0.5f}) {
        PointCloud cloud;
        for (int i = 0; i < 10000; ++i) cloud.push_back(5.f, 1.f, z);
        Params params = testParams();
        params.min_cluster_size = 1;
        Result result;
        ASSERT_NO_THROW(result = run(cloud, params)) << "z = " << z;
        expectConsistent(cloud, result);
        EXPECT_EQ(result.count(PointClass::Invalid), 0u);
        for (const ClusterSummary& c : result.clusters) EXPECT_LE(c.num_points, cloud.size());
        // With rings from the field too (all one ring).
        cloud.ring.assign(cloud.size(), 10);
        ASSERT_NO_THROW(result = run(cloud, params));
        expectConsistent(cloud, result);
    }
}

TEST(Robustness, AllPointsAboveTheSensorGiveNoGround) {
    sim::Scan scan = urbanScan();
    for (float& z : scan.cloud.z) z += 5.f;  // the whole scene lifted 5 m: ground 3.27 m above
    const Result result = run(scan.cloud);
    expectConsistent(scan.cloud, result);
    EXPECT_EQ(result.count(PointClass::Ground), 0u);
    EXPECT_EQ(result.terrain.seed_node, -1);
    EXPECT_GT(result.count(PointClass::NonGround), 0u);
}

TEST(Robustness, HalfSphereFieldOfViewStillFindsGroundAhead) {
    const sim::Scan full = urbanScan();
    sim::Scan half;
    const PointCloud& c = full.cloud;
    for (std::size_t i = 0; i < c.size(); ++i) {
        if (!(c.x[i] > 0.f)) continue;
        half.cloud.push_back(c.x[i], c.y[i], c.z[i], c.intensity[i]);
        half.cloud.ring.push_back(c.ring[i]);
        half.cloud.time.push_back(c.time[i]);
        half.gt.cls.push_back(full.gt.cls[i]);
        half.gt.instance.push_back(full.gt.instance[i]);
        half.gt.height_above_ground.push_back(full.gt.height_above_ground[i]);
    }
    ASSERT_GT(half.cloud.size(), 1000u);
    const Result result = run(half.cloud);
    expectConsistent(half.cloud, result);
    EXPECT_GE(result.terrain.seed_node, 0);
    const test::SceneScores scores = test::scoreScene(half.gt, result.labels);
    EXPECT_GE(scores.f1(), 0.97) << "P " << scores.precision() << " R " << scores.recall();
    EXPECT_EQ(scores.high_obstacle_as_ground, 0u);
}

// ---- Rings ----

void expectRowsInRange(const Pipeline& pipeline, const Result& result) {
    const RangeImage& image = pipeline.rangeImage();
    ASSERT_EQ(image.row().size(), result.labels.size());
    for (std::size_t i = 0; i < result.labels.size(); ++i) {
        const int row = image.row()[i], col = image.col()[i];
        if (result.labels[i] == PointClass::Invalid) continue;
        ASSERT_GE(row, 0) << "point " << i;
        ASSERT_LT(row, image.rows()) << "point " << i;
        ASSERT_GE(col, 0) << "point " << i;
        ASSERT_LT(col, image.cols()) << "point " << i;
    }
}

/// A cloud whose ring field is unusable: consistent labels, rows in range, rings not taken from
/// the field, and exactly the labels and ids of the same cloud without rings (`expected`).
void expectRingFallback(const PointCloud& cloud, const Pipeline& pipeline, const Result& result,
                        const Result& expected) {
    expectConsistent(cloud, result);
    expectRowsInRange(pipeline, result);
    EXPECT_NE(pipeline.rangeImage().source(), RingSource::Field);
    EXPECT_EQ(result.labels, expected.labels);
    EXPECT_EQ(result.cluster_id, expected.cluster_id);
}

TEST(Robustness, RingVectorShorterThanCloudIsTreatedAsAbsent) {
    const sim::Scan scan = urbanScan();
    PointCloud without = scan.cloud;
    without.ring.clear();
    PointCloud shorter = scan.cloud;
    shorter.ring.resize(shorter.size() / 2);
    ASSERT_FALSE(shorter.hasRing());

    Pipeline reference(testParams()), pipeline(testParams());
    Result expected, result;
    reference.process(without, {}, expected);
    pipeline.process(shorter, {}, result);
    expectRingFallback(shorter, pipeline, result, expected);
}

TEST(Robustness, RingValuesOutOfRangeFallBack) {
    const sim::Scan scan = urbanScan();
    PointCloud without = scan.cloud;
    without.ring.clear();
    Pipeline reference(testParams());
    Result expected;
    reference.process(without, {}, expected);

    for (const uint16_t bad : {uint16_t(64), uint16_t(1000), uint16_t(65535)}) {
        PointCloud cloud = scan.cloud;
        for (std::size_t i = 0; i < cloud.size(); i += 97) cloud.ring[i] = bad;
        Pipeline pipeline(testParams());  // num_rings = 64
        Result result;
        pipeline.process(cloud, {}, result);
        SCOPED_TRACE(bad);
        expectRingFallback(cloud, pipeline, result, expected);
    }
}

// docs/input-contract.md: an explicit ring_source that cannot read the cloud is an InputError
// from process(); the pipeline goes on, labelling the next frame as a new pipeline would.
TEST(Robustness, ExplicitRingSourceThatCannotReadTheCloudThrowsAndThePipelineGoesOn) {
    const sim::Scan scan = urbanScan();
    PointCloud without = scan.cloud;
    without.ring.clear();
    PointCloud out_of_range = scan.cloud;
    out_of_range.ring[0] = 64;  // num_rings = 64
    for (const bool face_rule : {false, true}) {
        Params params = testParams();
        params.ring_source = "field";
        if (face_rule) params.vertical_face_min_rise = 0.25, params.vertical_face_min_length = 0;
        SCOPED_TRACE(face_rule ? "face rule under every ground point" : "defaults");
        const Result expected = run(scan.cloud, params);
        Pipeline pipeline(params);
        Result result;
        for (const PointCloud* bad : {&without, &out_of_range}) {
            try {
                pipeline.process(*bad, {}, result);
                ADD_FAILURE() << "no InputError";
            } catch (const InputError& e) {
                EXPECT_EQ(std::string(e.what()).rfind("ring_source = field: ", 0), 0u) << e.what();
            }
            pipeline.process(scan.cloud, {}, result);
            expectConsistent(scan.cloud, result);
            EXPECT_EQ(result.labels, expected.labels);
            EXPECT_EQ(result.cluster_id, expected.cluster_id);
        }
    }
    Params params = testParams();
    params.ring_source = "scan_order";
    PointCloud shuffled = without;  // no ring to be found in the storage order
    std::mt19937 rng(1);
    for (std::size_t i = shuffled.size() - 1; i > 0; --i) {
        const std::size_t j = rng() % (i + 1);
        std::swap(shuffled.x[i], shuffled.x[j]), std::swap(shuffled.y[i], shuffled.y[j]);
        std::swap(shuffled.z[i], shuffled.z[j]);
    }
    EXPECT_THROW(run(shuffled, params), InputError);
}

// docs/input-contract.md: a time or intensity field of another length than x is not used.
TEST(Robustness, TimeAndIntensityOfAnotherLengthAreNotUsed) {
    const sim::Scan scan = urbanScan();
    FrameInput moving;
    moving.linear_velocity = Eigen::Vector3d(5.0, 0.0, 0.0);
    moving.angular_velocity = Eigen::Vector3d(0.0, 0.0, 0.2);
    PointCloud without_time = scan.cloud;
    without_time.time.clear();
    const Result expected = run(without_time, testParams(), moving);
    PointCloud odd = scan.cloud;
    odd.time.pop_back();
    odd.intensity.clear();
    ASSERT_FALSE(odd.hasTime());
    const Result result = run(odd, testParams(), moving);
    expectConsistent(odd, result);
    EXPECT_EQ(result.labels, expected.labels);
    EXPECT_EQ(result.cluster_id, expected.cluster_id);
}

// ---- Per-point times with deskew ----

TEST(Robustness, UnsortedAndNaNTimesWithDeskew) {
    const sim::Scan scan = urbanScan();
    FrameInput input;
    input.linear_velocity = Eigen::Vector3d(1.0, 0.0, 0.0);
    input.angular_velocity = Eigen::Vector3d(0.0, 0.0, 0.1);
    const Result still = run(scan.cloud);

    // Unsorted: the times shuffled among the points (moves of at most 0.1 m and 0.6 deg).
    PointCloud shuffled = scan.cloud;
    std::mt19937 rng(3);
    std::shuffle(shuffled.time.begin(), shuffled.time.end(), rng);
    const Result a = run(shuffled, testParams(), input);
    expectConsistent(shuffled, a);
    EXPECT_EQ(a.count(PointClass::Invalid), still.count(PointClass::Invalid));
    EXPECT_GT(a.count(PointClass::Ground), still.count(PointClass::Ground) * 9 / 10);
    const Result again = run(shuffled, testParams(), input);
    EXPECT_EQ(a.labels, again.labels);
    EXPECT_EQ(a.cluster_id, again.cluster_id);

    // NaN / inf times: such a point is not moved (same label as without deskew when all times
    // are bad).
    PointCloud nan_times = scan.cloud;
    for (float& t : nan_times.time) t = kNaN;
    const Result b = run(nan_times, testParams(), input);
    expectConsistent(nan_times, b);
    EXPECT_EQ(b.labels, still.labels);
    EXPECT_EQ(b.cluster_id, still.cluster_id);
    PointCloud some_bad = scan.cloud;
    for (std::size_t i = 0; i < some_bad.size(); i += 7) some_bad.time[i] = i % 2 ? kNaN : kInf;
    const Result c = run(some_bad, testParams(), input);
    expectConsistent(some_bad, c);
    EXPECT_GT(c.count(PointClass::Ground), still.count(PointClass::Ground) * 9 / 10);

    // Absurd times (absolute instead of relative) move points out of the range window: Invalid.
    PointCloud absolute = scan.cloud;
    for (float& t : absolute.time) t += 1.7e9f;
    const Result d = run(absolute, testParams(), input);
    expectConsistent(absolute, d);
    EXPECT_EQ(d.count(PointClass::Invalid), absolute.size());

    // A point moved inside min_range (onto the origin here) has left the range window too.
    PointCloud two;
    two.push_back(10.f, 0.f, -1.73f), two.push_back(10.f, 5.f, -1.73f);
    two.time = {0.05f, 0.f};
    FrameInput fast;
    fast.linear_velocity = Eigen::Vector3d(-200.0, 0.0, 34.6);  // 10 m, 1.73 m in 0.05 s
    fast.angular_velocity = Eigen::Vector3d::Zero();
    const Params params = testParams();
    ASSERT_GT(params.min_range, 1.0);
    const Result e = run(two, params, fast);
    expectConsistent(two, e);
    EXPECT_EQ(e.labels[0], PointClass::Invalid);
    EXPECT_NE(e.labels[1], PointClass::Invalid);
}

// ---- Parameters ----

std::string configErrorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const ConfigError& e) {
        return e.what();
    }
    return "";
}

bool mentions(const std::string& message, const std::string& needle) {
    return message.find(needle) != std::string::npos;
}

TEST(Robustness, ParamsValidateRejectsOutOfRangeNamingTheKey) {
    struct Case {
        const char* key;
        std::function<void(Params&)> set;
    };
    const Case cases[] = {
        {"tgf_resolution", [](Params& p) { p.tgf_resolution = -1.0; }},
        {"num_rings", [](Params& p) { p.num_rings = 0; }},
        {"min_cluster_size", [](Params& p) { p.min_cluster_size = 100, p.max_cluster_size = 10; }},
        {"max_cluster_size", [](Params& p) { p.min_cluster_size = 100, p.max_cluster_size = 10; }},
        {"sensor_height", [](Params& p) { p.sensor_height = std::nan(""); }},
        {"max_range", [](Params& p) { p.max_range = std::numeric_limits<double>::infinity(); }},
        {"ground_dist", [](Params& p) { p.ground_dist = -0.1; }},
        // Above 64 the node fitting's LPR used 64 points whatever the value said.
        {"lpr_num_points", [](Params& p) { p.lpr_num_points = 65; }},
    };
    for (const Case& c : cases) {
        Params params;
        c.set(params);
        const std::string message = configErrorOf([&] { params.validate(); });
        EXPECT_TRUE(mentions(message, c.key)) << c.key << ": '" << message << "'";
        EXPECT_TRUE(mentions(configErrorOf([&] { Pipeline pipeline(params); }), c.key)) << c.key;
    }
}

TEST(Robustness, ParamsTextRejectsOutOfRangeNamingFileLineAndKey) {
    struct Case {
        const char* text;
        const char* where;
        const char* key;
    };
    const Case cases[] = {
        {"tgf_resolution: -1\n", "bad.yaml:1", "tgf_resolution"},
        {"# comment\nnum_rings: 0\n", "bad.yaml:2", "num_rings"},
        {"sensor_height: nan\n", "bad.yaml:1", "sensor_height"},
        {"sensor_height: .nan\n", "bad.yaml:1", "sensor_height"},
        {"max_range: inf\n", "bad.yaml:1", "max_range"},
        {"[travel]\ntgf_resolution = -0.5\n", "bad.yaml:2", "tgf_resolution"},
        {"num_rings = 0\n", "bad.yaml:1", "num_rings"},
        {"tgf_resolutoin: 4\n", "bad.yaml:1", "tgf_resolutoin"},
        {"min_cluster_size: 1e99\n", "bad.yaml:1", "min_cluster_size"},
    };
    for (const Case& c : cases) {
        Params params;
        const std::string message =
            configErrorOf([&] { applyParamsText(c.text, "bad.yaml", params); });
        EXPECT_TRUE(mentions(message, c.where)) << c.text << " -> '" << message << "'";
        EXPECT_TRUE(mentions(message, c.key)) << c.text << " -> '" << message << "'";
    }
    // Cross-parameter consistency is checked by validate().
    Params params;
    ASSERT_NO_THROW(
        applyParamsText("min_cluster_size: 100\nmax_cluster_size: 10\n", "bad.yaml", params));
    const std::string message = configErrorOf([&] { params.validate(); });
    EXPECT_TRUE(mentions(message, "min_cluster_size")) << message;
    EXPECT_TRUE(mentions(message, "max_cluster_size")) << message;
}

TEST(Robustness, HugeGridIsAConfigErrorNotAnAllocation) {
    const double rss_before = peakRssMb();
    Params params;
    params.max_range = 2000.0;
    params.tgf_resolution = 0.25;  // 16,000 cells per side = 1e9 nodes
    EXPECT_TRUE(mentions(configErrorOf([&] { params.validate(); }), "max_grid_cells_per_side"));
    EXPECT_TRUE(mentions(configErrorOf([&] { Pipeline pipeline(params); }), "tgf_resolution"));

    Params from_text;
    applyParamsText("max_range: 1000\ntgf_resolution: 0.5\n", "big.yaml", from_text);
    EXPECT_TRUE(
        mentions(configErrorOf([&] { Pipeline pipeline(from_text); }), "max_grid_cells_per_side"));
    // Exactly at the limit is accepted; one more cell is not.
    Params edge;
    edge.tgf_resolution = 0.25;
    edge.max_range = 0.5 * edge.max_grid_cells_per_side * edge.tgf_resolution;
    EXPECT_NO_THROW(edge.validate());
    edge.max_range += 0.01;
    EXPECT_TRUE(mentions(configErrorOf([&] { edge.validate(); }), "max_grid_cells_per_side"));
    std::printf("[ info ] peak RSS %.0f MB before, %.0f MB after the rejected grids\n", rss_before,
                peakRssMb());
}

// Rings and columns each within their ranges can still ask for a 67-million-cell range image
// (9 GB of buffers mapped by the constructor): a configuration error naming both keys.
TEST(Robustness, HugeRangeImageIsAConfigErrorNotAnAllocation) {
    Params params;
    params.num_rings = 1024;
    params.num_columns = 65536;
    const std::string message = configErrorOf([&] { Pipeline pipeline(params); });
    EXPECT_TRUE(mentions(message, "range image too large")) << message;
    EXPECT_TRUE(mentions(message, "num_columns")) << message;
    // The 128-beam table with 16384 columns is exactly at the limit; the presets are far below.
    params.num_rings = 64;
    params.elevation_table = "os128";
    params.num_columns = 16384;
    EXPECT_NO_THROW(params.validate());
    params.num_columns = 16385;
    EXPECT_TRUE(mentions(configErrorOf([&] { params.validate(); }), "range image too large"));
}

// ---- Resource limits ----

/// A dense seeded cloud: ground with 2 cm noise out to `radius` (density falling as 1/r, like a
/// spinning LiDAR) and `num_boxes` 2 x 2 x 1.5 m boxes. is_box[i] = 1 for points of a box
/// higher than 0.3 m above the ground.
PointCloud denseCloud(std::size_t n, float radius, int num_boxes, std::vector<uint8_t>& is_box) {
    std::mt19937 rng(2026);
    std::uniform_real_distribution<float> unit(0.f, 1.f);
    std::normal_distribution<float> noise(0.f, 0.02f);
    const float ground = -static_cast<float>(kSensorHeight);
    PointCloud cloud;
    cloud.reserve(n);
    is_box.clear();
    is_box.reserve(n);
    const std::size_t box_points = n / 5;
    for (std::size_t i = 0; i < n - box_points; ++i) {
        const float r = 3.f + (radius - 3.f) * unit(rng);
        const float a = 2.f * static_cast<float>(M_PI) * unit(rng);
        cloud.push_back(r * std::cos(a), r * std::sin(a), ground + noise(rng));
        is_box.push_back(0);
    }
    for (std::size_t i = 0; i < box_points; ++i) {
        const int b = static_cast<int>(i % num_boxes);
        const float a = 2.f * static_cast<float>(M_PI) * b / num_boxes;
        const float r = 10.f + 40.f * static_cast<float>(b % 5) / 5.f;
        const float cx = r * std::cos(a), cy = r * std::sin(a);
        // A point on the box's top or one of its four sides.
        float u = 2.f * unit(rng) - 1.f, v = 2.f * unit(rng) - 1.f, h = 1.5f * unit(rng);
        switch (rng() % 5) {
            case 0:
                h = 1.5f;
                break;
            case 1:
                u = 1.f;
                break;
            case 2:
                u = -1.f;
                break;
            case 3:
                v = 1.f;
                break;
            default:
                v = -1.f;
                break;
        }
        cloud.push_back(cx + u, cy + v, ground + h);
        is_box.push_back(h > 0.3f);
    }
    return cloud;
}

TEST(Robustness, TwoMillionPoints) {
    std::vector<uint8_t> is_box;
    const PointCloud cloud = denseCloud(2000000, 79.f, 30, is_box);
    Pipeline pipeline(testParams());
    Result result;
    const auto t0 = std::chrono::steady_clock::now();
    ASSERT_NO_THROW(pipeline.process(cloud, {}, result));
    const double first_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    const auto t1 = std::chrono::steady_clock::now();
    pipeline.process(cloud, {}, result);  // warm: buffers reused
    const double warm_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t1).count();
    expectConsistent(cloud, result);
    EXPECT_EQ(result.count(PointClass::Invalid), 0u);
    std::size_t ground_points = 0, ground_as_ground = 0, box_as_ground = 0;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        if (is_box[i]) box_as_ground += result.labels[i] == PointClass::Ground;
        if (i < cloud.size() - cloud.size() / 5) {
            ++ground_points;
            ground_as_ground += result.labels[i] == PointClass::Ground;
        }
    }
    EXPECT_GE(double(ground_as_ground) / double(ground_points), 0.9);
    EXPECT_EQ(box_as_ground, 0u);
    EXPECT_GT(result.clusters.size(), 0u);
    std::printf(
        "[ info ] 2,000,000 points: first frame %.0f ms, warm frame %.0f ms (ground %.0f"
        " ms, objects %.0f ms), %zu clusters, peak RSS %.0f MB\n",
        first_ms, warm_ms, result.timings.ground_total, result.timings.objects_total,
        result.clusters.size(), peakRssMb());
}

TEST(Robustness, OneKilometreRange) {
    Params params = testParams();
    params.tgf_resolution = 4.0;
    params.max_range = 1000.0;  // 500 cells per side, 1,000,000 nodes
    ASSERT_NO_THROW(params.validate());

    // A 20 m wide road from -999 m to +999 m, ground around the sensor, and a 1.5 m box on the
    // road 950 m ahead.
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> unit(0.f, 1.f);
    std::normal_distribution<float> noise(0.f, 0.02f);
    const float ground = -static_cast<float>(kSensorHeight);
    PointCloud cloud;
    std::vector<uint8_t> kind;  // 0 near ground, 1 road, 2 box above 0.3 m
    for (int i = 0; i < 100000; ++i) {
        const float r = 3.f + 27.f * unit(rng), a = 2.f * static_cast<float>(M_PI) * unit(rng);
        cloud.push_back(r * std::cos(a), r * std::sin(a), ground + noise(rng));
        kind.push_back(0);
    }
    for (int i = 0; i < 400000; ++i) {
        cloud.push_back(-999.f + 1998.f * unit(rng), -10.f + 20.f * unit(rng), ground + noise(rng));
        kind.push_back(1);
    }
    for (int i = 0; i < 2000; ++i) {
        const float h = 0.35f + 1.15f * unit(rng);
        cloud.push_back(950.f + (i % 2 ? 1.f : -1.f), -1.f + 2.f * unit(rng), ground + h);
        kind.push_back(2);
    }

    const double rss_before = peakRssMb();
    const auto t0 = std::chrono::steady_clock::now();
    Pipeline pipeline(params);
    Result result;
    ASSERT_NO_THROW(pipeline.process(cloud, {}, result));
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    expectConsistent(cloud, result);
    std::size_t too_near = 0;  // road points under the vehicle, closer than min_range
    for (std::size_t i = 0; i < cloud.size(); ++i)
        too_near += std::hypot(cloud.x[i], cloud.y[i], cloud.z[i]) < params.min_range;
    EXPECT_EQ(result.count(PointClass::Invalid), too_near);
    EXPECT_EQ(result.terrain.cells_per_side, 500);
    std::size_t far_road = 0, far_ground = 0, box_ground = 0;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        if (kind[i] == 1 && cloud.x[i] > 900.f && std::abs(cloud.x[i] - 950.f) > 10.f) {
            ++far_road;
            far_ground += result.labels[i] == PointClass::Ground;
        }
        if (kind[i] == 2) box_ground += result.labels[i] == PointClass::Ground;
    }
    ASSERT_GT(far_road, 1000u);
    EXPECT_GE(double(far_ground) / double(far_road), 0.95);
    EXPECT_EQ(box_ground, 0u);
    std::printf(
        "[ info ] 1 km range, r = 4 m (%d cells per side, %zu nodes), %zu points: "
        "construct + first frame %.0f ms, peak RSS %.0f MB (was %.0f MB before), "
        "sizeof(TriNode) = %zu B\n",
        result.terrain.cells_per_side, result.terrain.nodes.size(), cloud.size(), ms, peakRssMb(),
        rss_before, sizeof(TriNode));
}

// ---- Allocation ----

/// Calls of operator new made by `f` on this thread.
std::size_t allocationsOf(const std::function<void()>& f) {
    t_allocations = 0;
    t_count_allocations = true;
    f();
    t_count_allocations = false;
    return t_allocations;
}

// Pipeline.hpp / Preprocessing.hpp: every buffer is reused, so once a Pipeline and a Result have
// seen a set of frames, processing those frames again allocates nothing, on every path that picks
// the rows (ring field, scan order, elevation table) and with the face rule in either scope.
TEST(Robustness, NoAllocationOnceEveryFrameWasSeen) {
    const sim::Scan urban = urbanScan();
    const sim::Scene cars = sim::parkedCarRow(8, 1.0);
    const sim::Scan row =
        sim::scan(cars, testLidar(), sim::sensorPoseAt(cars, 0, 0, kSensorHeight, 0, 0, 0));
    PointCloud urban_scan_order = urban.cloud;  // a KITTI .bin: rings from the scan order
    urban_scan_order.ring.clear();
    FrameInput moving;  // deskew
    moving.linear_velocity = Eigen::Vector3d(5.0, 0.0, 0.0);
    moving.angular_velocity = Eigen::Vector3d(0.0, 0.0, 0.2);
    const std::vector<std::pair<const PointCloud*, FrameInput>> frames = {
        {&urban.cloud, {}}, {&row.cloud, moving}, {&urban_scan_order, {}}};

    struct Case {
        const char* name;
        std::function<void(Params&)> set;
    };
    const Case cases[] = {
        {"defaults", [](Params&) {}},
        {"rings from the table", [](Params& p) { p.ring_source = "table"; }},
        {"face rule under every ground point",
         [](Params& p) {
             p.vertical_face_min_rise = 0.25, p.vertical_face_min_length = 0.0;
             p.vertical_face_min_foot_height = 0.05;
         }},
        {"face rule under walls",
         [](Params& p) { p.vertical_face_min_rise = 0.25, p.cluster_face_feet = true; }},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        Params params = testParams();
        c.set(params);
        Pipeline pipeline(params);
        Result result;
        pipeline.reserve(result);
        for (const auto& [cloud, input] : frames) pipeline.process(*cloud, input, result);
        for (const auto& [cloud, input] : frames) {
            EXPECT_EQ(allocationsOf([&] { pipeline.process(*cloud, input, result); }), 0u)
                << cloud->size() << " points";
            expectConsistent(*cloud, result);
        }
    }
}

// ---- Threads ----

TEST(Robustness, FourThreadsEachWithItsOwnPipelineMatchSingleThreaded) {
    const sim::Scan scan = urbanScan();
    const Result reference = run(scan.cloud);
    ASSERT_GT(reference.clusters.size(), 0u);

    constexpr int kThreads = 4, kRuns = 20;
    std::vector<int> mismatches(kThreads, 0);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t) {
        threads.emplace_back([&, t] {
            Pipeline pipeline(testParams());
            Result result;
            for (int k = 0; k < kRuns; ++k) {
                pipeline.process(scan.cloud, {}, result);
                mismatches[t] += result.labels != reference.labels ||
                                 result.cluster_id != reference.cluster_id ||
                                 result.clusters.size() != reference.clusters.size();
            }
        });
    }
    for (std::thread& th : threads) th.join();
    for (int t = 0; t < kThreads; ++t) EXPECT_EQ(mismatches[t], 0) << "thread " << t;
}

// The apps' -j N helpers (apps/OrderedWork.hpp), also run under ThreadSanitizer: items are
// consumed in input order whatever order the workers finish them in, and a worker's exception
// reaches the caller at its item's turn, after every earlier item.
TEST(Robustness, ThreadsOfForEachInOrderConsumeInInputOrder) {
    constexpr std::size_t kItems = 200;
    for (unsigned workers : {1u, 2u, 3u}) {
        std::vector<std::size_t> consumed;
        apps::forEachInOrder<std::size_t>(
            kItems, workers, [&] { return consumed.size() < 3; },  // 3 in order first
            [](unsigned) {},
            [](unsigned, std::size_t i, std::size_t& slot) {
                // Uneven work so that workers overtake each other.
                if (i % 7 == 0) std::this_thread::sleep_for(std::chrono::microseconds(200));
                slot = i * i;
            },
            [&](std::size_t i, std::size_t& slot) {
                EXPECT_EQ(slot, i * i);
                consumed.push_back(i);
            });
        ASSERT_EQ(consumed.size(), kItems) << workers;
        for (std::size_t i = 0; i < kItems; ++i) EXPECT_EQ(consumed[i], i) << workers;
    }
}

// As travel-kitti: the state settles while an item is produced (TRAVEL's first frame); that item
// is consumed after the fork, from its own slot, still in order; all-sequential runs too.
TEST(Robustness, ThreadsOfForEachInOrderConsumeTheSettlingItemAfterTheFork) {
    for (const std::size_t items : {std::size_t{2}, std::size_t{3}, std::size_t{50}}) {
        std::size_t produced_before_fork = 0;
        bool forked = false;
        std::vector<std::size_t> consumed;
        std::vector<bool> consumed_after_fork;
        apps::forEachInOrder<std::vector<std::size_t>>(
            items, 2u, [&] { return produced_before_fork < 3; },  // settles on item 2
            [&](unsigned) { forked = true; },
            [&](unsigned, std::size_t i, std::vector<std::size_t>& slot) {
                if (!forked) ++produced_before_fork;
                slot.assign(1000, i);
            },
            [&](std::size_t i, std::vector<std::size_t>& slot) {
                ASSERT_EQ(slot.size(), 1000u);
                EXPECT_EQ(slot[999], i);
                consumed.push_back(i);
                consumed_after_fork.push_back(forked);
            });
        ASSERT_EQ(consumed.size(), items);
        for (std::size_t i = 0; i < items; ++i) EXPECT_EQ(consumed[i], i) << items;
        EXPECT_EQ(forked, items > 3) << items;
        if (items > 3) {
            EXPECT_FALSE(consumed_after_fork[1]);
            EXPECT_TRUE(consumed_after_fork[2]);  // the settling item
        }
    }
}

TEST(Robustness, ThreadsOfBackgroundBuildsGiveEachItemOnceBuiltAndRethrowItsError) {
    std::atomic<int> built{0};
    {
        apps::BackgroundBuilds<std::unique_ptr<std::vector<int>>> items(
            3, [&](unsigned i) -> std::unique_ptr<std::vector<int>> {
                if (i == 1) throw std::runtime_error("item 1 failed");
                std::this_thread::sleep_for(std::chrono::microseconds(300 * (3 - i)));
                ++built;
                return std::make_unique<std::vector<int>>(1000, int(i));
            });
        const auto two = items.take(2);  // any order
        ASSERT_TRUE(two);
        EXPECT_EQ(two->at(999), 2);
        const auto zero = items.take(0);
        ASSERT_TRUE(zero);
        EXPECT_EQ(zero->at(0), 0);
        EXPECT_THROW(items.take(1), std::runtime_error);
        EXPECT_THROW(items.take(3), std::out_of_range);
    }
    EXPECT_EQ(built.load(), 2);
    // Items never taken are joined by the destructor.
    apps::BackgroundBuilds<int> untaken(2, [](unsigned i) { return int(i); });
}

TEST(Robustness, ThreadsOfOrderedSlotsConsumeInPreparationOrder) {
    struct Slot {
        std::size_t item = 0, result = 0;
    };
    constexpr std::size_t kItems = 300;
    for (unsigned workers : {1u, 2u, 3u}) {
        std::vector<std::size_t> consumed;
        const auto consume = [&](Slot& s) {
            EXPECT_EQ(s.result, s.item * 3 + 1);
            consumed.push_back(s.item);
        };
        {
            apps::OrderedSlots<Slot> pool(workers, [](unsigned, Slot& s) {
                if (s.item % 5 == 0) std::this_thread::sleep_for(std::chrono::microseconds(200));
                s.result = s.item * 3 + 1;
            });
            for (std::size_t i = 0; i < kItems; ++i) {
                Slot& s = pool.next(consume);
                s.item = i;
                if (i % 11 == 0) {  // done by the caller, as travel-rawlog's unsettled frames
                    s.result = i * 3 + 1;
                    pool.submitDone();
                } else {
                    pool.submit();
                }
            }
            pool.drain(consume);
        }
        ASSERT_EQ(consumed.size(), kItems) << workers;
        for (std::size_t i = 0; i < kItems; ++i) EXPECT_EQ(consumed[i], i) << workers;
    }
    // A worker's exception: the items before it are consumed, then it is rethrown.
    std::vector<std::size_t> consumed;
    const auto consume = [&](Slot& s) { consumed.push_back(s.item); };
    apps::OrderedSlots<Slot> pool(2, [](unsigned, Slot& s) {
        if (s.item == 6) throw std::runtime_error("item 6 failed");
    });
    const auto run = [&] {
        for (std::size_t i = 0; i < 20; ++i) {
            Slot& s = pool.next(consume);
            s.item = i;
            pool.submit();
        }
        pool.drain(consume);
    };
    EXPECT_THROW(run(), std::runtime_error);
    EXPECT_EQ(consumed, (std::vector<std::size_t>{0, 1, 2, 3, 4, 5}));
}

}  // namespace
}  // namespace travel
