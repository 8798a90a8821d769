// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The object-segmentation failures seen on scans the project was never tuned on (issue 14),
// reproduced with realistic cars (sim::realisticCar: body, tyres, pillars, roof, seats, glass
// windows that rays pass through, dark paint with missing returns) and exact ground truth:
//   - a car 2-3 m beside a 64-beam and a 128-beam sensor (split into six clusters on real data);
//   - parked cars at 20-25 m (a third of a car lost: its far side seen through the windows);
//   - moving cars at 20-25 m straddling the sweep's start/end azimuth (split in two).
// Each test prints its figures (--gtest_filter=HardObjects.*) and asserts the level reached,
// with margin.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <map>
#include <vector>

#include "MergeDiagnosticPairs.hpp"
#include "SceneMetrics.hpp"
#include "travel/ParamsIO.hpp"
#include "travel/Pipeline.hpp"
#include "travel/Preprocessing.hpp"
#include "travel/eval/MergeDiagnostics.hpp"
#include "travel/sim/Scenes.hpp"
#include "travel/sim/SyntheticLidar.hpp"

namespace travel {
namespace {

struct Sensor {
    const char* name;
    sim::LidarModel model;
    Params params;
};

// The KITTI HDL-64E and an OS1-128, both 1.73 m up. min_range 1 m: a car 2 m away is nearer
// than KITTI's 2.7 m self-return cut.
Sensor hdl64() {
    Params p;
    p.sensor_height = sim::kSensorHeight;
    p.min_range = 1.0;
    return {"hdl64", sim::LidarModel::hdl64(), p};
}

Sensor os128() {
    Sensor s = hdl64();
    s.name = "os128";
    s.model = sim::LidarModel::os128();
    s.params.num_rings = 128;
    s.params.num_columns = 1024;
    s.params.elevation_table = "os128";
    return s;
}

struct ObjectRun {
    sim::Scan scan;
    Result result;
};

ObjectRun run(const sim::Scene& scene, Sensor sensor) {
    sensor.model.range_noise_sigma = 0.01;
    sensor.model.seed = 7;
    sensor.model.max_range = sensor.params.max_range;
    ObjectRun r;
    r.scan =
        sim::scan(scene, sensor.model, sim::sensorPoseAt(scene, 0, 0, sim::kSensorHeight, 0, 0, 0));
    Pipeline pipeline(sensor.params);
    pipeline.process(r.scan.cloud, {}, r.result);
    return r;
}

test::ObjectScore score(const ObjectRun& r, uint32_t id, const char* what) {
    const test::ObjectScore s =
        test::scoreObject(r.scan.gt, r.result.labels, r.result.cluster_id, id);
    std::printf("%-30s car %u coverage %.3f purity %.3f (%zu non-ground points)\n", what, id,
                s.coverage, s.purity, s.points);
    return s;
}

TEST(HardObjects, RealisticCarBesideA64And128BeamSensor) {
    for (const Sensor& sensor : {hdl64(), os128()}) {
        for (const double gap : {2.0, 3.0}) {
            SCOPED_TRACE(sensor.name);
            char what[64];
            std::snprintf(what, sizeof what, "car_beside_%.0fm_%s", gap, sensor.name);
            const test::ObjectScore car =
                score(run(sim::realisticCarBesideSensor(gap), sensor), 1, what);
            // 1.000 before and after the see-through / seam / range-scaled merges: with every
            // point valid, windows and missing returns do not split a car this near.
            EXPECT_GE(car.coverage, 0.98);
            EXPECT_GE(car.purity, 0.99);
        }
    }
}

// As the instance evaluator counts: all the instance's points, whatever their class (invalid
// ones too), against its best cluster. Also how many clusters hold >= 10 of its points.
double evaluatorCoverage(const ObjectRun& r, uint32_t id, std::size_t& clusters) {
    std::map<uint32_t, std::size_t> per_cluster;
    std::size_t points = 0;
    for (std::size_t i = 0; i < r.scan.gt.size(); ++i) {
        if (r.scan.gt.instance[i] != id) continue;
        ++points;
        if (r.result.cluster_id[i]) ++per_cluster[r.result.cluster_id[i]];
    }
    std::size_t best = 0;
    clusters = 0;
    for (const auto& [cluster, count] : per_cluster) {
        best = std::max(best, count);
        clusters += count >= 10;
    }
    return points ? double(best) / double(points) : 0.0;
}

// Ground recall within `radius` (xy) of the sensor, and the own vehicle's returns not Invalid.
struct NearScores {
    double ground_recall = 0;
    std::size_t ego_points = 0, ego_not_invalid = 0;
};

NearScores nearScores(const ObjectRun& r, double radius) {
    NearScores s;
    std::size_t ground = 0, found = 0;
    for (std::size_t i = 0; i < r.scan.gt.size(); ++i) {
        if (r.scan.gt.cls[i] == sim::NoReturn) continue;
        if (r.scan.gt.instance[i] == sim::kEgoVehicleId) {
            ++s.ego_points;
            s.ego_not_invalid += r.result.labels[i] != PointClass::Invalid;
        }
        if (r.scan.gt.cls[i] != sim::Ground ||
            std::hypot(r.scan.cloud.x[i], r.scan.cloud.y[i]) > radius)
            continue;
        ++ground;
        found += r.result.labels[i] == PointClass::Ground;
    }
    s.ground_recall = ground ? double(found) / double(ground) : 1.0;
    return s;
}

// The car beside the KITTI car (sim::egoVehicle under the sensor), its self returns removed
// by the defaults' 2.7 m sphere (before) and by the hdl64 preset's box around the car plus a
// 1 m sphere (after), on the HDL-64E and a 128-beam sensor on the same roof. Coverage as the
// instance evaluator counts it (invalid points against it). Before, not the object stage: the
// sphere drops the car's nearest points (invalid) and cuts it into its front, its rear and what
// the windows show: 0.234 (4 clusters) at 2 m, 0.849 at 2.5 m (hdl64; os128 0.263, 0.856), while
// about 400 returns of the own bonnet's front corners (2.7-2.95 m away) stay valid. After:
// 1.000 at both gaps, every own-car return invalid. At 3 m both give 1.000 (not run).
// Ground within 8 m: recall 1.000 both: on flat ground the lowest beam (-24.9 deg; OS1-128
// -22.5 deg) meets the road 3.7 m (4.2 m) away, farther than either filter reaches.
TEST(HardObjects, RealisticCarBesideTheKittiCar) {
    Sensor preset = hdl64();
    preset.params = loadPreset("hdl64");
    Sensor preset128 = os128();
    const Params rings128 = preset128.params;
    preset128.params = preset.params;
    preset128.params.num_rings = rings128.num_rings;
    preset128.params.num_columns = rings128.num_columns;
    preset128.params.elevation_table = rings128.elevation_table;
    for (const Sensor& with_box : {preset, preset128}) {
        Sensor sphere = with_box;  // the defaults' self filter: min_range 2.7 m, no box
        sphere.params.min_range = Params().min_range;
        sphere.params.self_box_min_x = sphere.params.self_box_max_x = 0.0;
        for (const double gap : {2.0, 2.5}) {
            SCOPED_TRACE(with_box.name);
            const sim::Scene scene = sim::realisticCarBesideEgoVehicle(gap);
            const ObjectRun before = run(scene, sphere), after = run(scene, with_box);
            std::size_t clusters_before = 0, clusters_after = 0;
            const double coverage_before = evaluatorCoverage(before, 1, clusters_before);
            const double coverage_after = evaluatorCoverage(after, 1, clusters_after);
            const test::ObjectScore car =
                test::scoreObject(after.scan.gt, after.result.labels, after.result.cluster_id, 1);
            const NearScores near_before = nearScores(before, 8.0);
            const NearScores near_after = nearScores(after, 8.0);
            std::printf(
                "car_beside_%.1fm_selfbox_%s coverage %.3f (%zu clusters) -> %.3f (%zu), purity "
                "%.3f; ground recall < 8 m %.4f -> %.4f; own car %zu/%zu -> %zu/%zu not invalid\n",
                gap, with_box.name, coverage_before, clusters_before, coverage_after,
                clusters_after, car.purity, near_before.ground_recall, near_after.ground_recall,
                near_before.ego_not_invalid, near_before.ego_points, near_after.ego_not_invalid,
                near_after.ego_points);
            EXPECT_GE(coverage_after, 0.98);
            EXPECT_EQ(clusters_after, 1u);
            EXPECT_GE(car.purity, 0.99);
            EXPECT_GE(near_after.ground_recall, near_before.ground_recall);
            EXPECT_GT(near_after.ego_points, 0u);
            EXPECT_EQ(near_after.ego_not_invalid, 0u);
        }
    }
}

// The self box is in the vehicle frame (after mount_*) and tested before deskew and levelling,
// whichever loop runs: a nuScenes-like mount (sensor x to the right, mount_yaw_deg -90).
TEST(SelfBox, VehicleFrameOnEveryPreprocessingPath) {
    Params p;
    p.min_range = 0.5;
    p.mount_yaw_deg = -90.0;
    p.self_box_min_x = -2.0, p.self_box_max_x = 3.0;
    p.self_box_min_y = -1.0, p.self_box_max_y = 1.0;
    p.self_box_min_z = -2.0, p.self_box_max_z = 0.0;
    PointCloud cloud;
    cloud.push_back(0.0f, 2.5f, -1.0f);  // vehicle (2.5, 0, -1): the bonnet, invalid
    cloud.push_back(2.5f, 0.0f, -1.0f);  // vehicle (0, -2.5, -1): beside the car, valid
    cloud.push_back(0.0f, 2.5f, 0.5f);   // above the box, valid
    cloud.push_back(0.0f, 3.5f, -1.0f);  // ahead of the box, valid
    const std::vector<uint8_t> expected = {0, 1, 1, 1};
    AlignedCloud out;
    preprocess(cloud, p, {}, out);  // the fast loop, no levelling
    EXPECT_EQ(out.valid, expected);
    FrameInput levelled;  // a 5 deg roll: the general loop
    levelled.vehicle_attitude =
        Eigen::AngleAxisd(5.0 * M_PI / 180.0, Eigen::Vector3d::UnitX()).toRotationMatrix();
    preprocess(cloud, p, levelled, out);
    EXPECT_EQ(out.valid, expected);
    FrameInput moving;  // deskew by 1 m: the body moves with the sensor, still invalid
    moving.linear_velocity = Eigen::Vector3d(0.0, 10.0, 0.0);
    moving.angular_velocity = Eigen::Vector3d::Zero();
    cloud.time = {0.1f, 0.1f, 0.1f, 0.1f};
    preprocess(cloud, p, moving, out);
    EXPECT_EQ(out.valid, expected);
    EXPECT_EQ(out.num_valid, 3u);
    Params no_box = p;  // the defaults' empty box filters nothing
    no_box.self_box_min_x = no_box.self_box_max_x = 0.0;
    cloud.time.clear();
    preprocess(cloud, no_box, {}, out);
    EXPECT_EQ(out.num_valid, 4u);
}

// See-through linkage must not take an object behind a fence for the fence's far side: a car
// 1.2 m behind a fence of 1 m panels with 0.3 m gaps (one cluster: the gaps are below T_horz;
// the cabin shows above the fence), and
// behind a 1.8 m one (seen only through the gaps).
TEST(HardObjects, CarBehindAFenceWithGapsStaysApart) {
    for (const double fence_height : {1.0, 1.8}) {
        sim::Scene scene;
        for (int k = 0; k < 16; ++k) {
            sim::Wall panel;
            panel.id = 10 + k;
            panel.a = {-11.0 + 1.3 * k, 8.0};
            panel.b = {-10.0 + 1.3 * k, 8.0};
            panel.thickness = 0.05;
            panel.height = fence_height;
            scene.walls.push_back(panel);
        }
        scene.boxes = sim::realisticCar(1, {0.0, 10.1}, 0.0);
        const ObjectRun r = run(scene, hdl64());
        char what[64];
        std::snprintf(what, sizeof what, "behind_%.1fm_fence", fence_height);
        const test::ObjectScore car = score(r, 1, what);
        EXPECT_GE(car.purity, 0.99);
    }
}

TEST(HardObjects, ParkedCarsAt20To25Metres) {
    for (const Sensor& sensor : {hdl64(), os128()}) {
        SCOPED_TRACE(sensor.name);
        const ObjectRun r = run(sim::parkedCarsAt20To25Metres(), sensor);
        for (uint32_t id = 1; id <= 3; ++id) {
            char what[64];
            std::snprintf(what, sizeof what, "parked_20_25m_%s", sensor.name);
            const test::ObjectScore car = score(r, id, what);
            // Before see-through linkage: hdl64 0.978 / 0.927 / 0.973, os128 0.946 / 0.896 /
            // 0.904 (the far side seen through the windows apart); after: 0.978 / 0.978 / 0.973,
            // 0.966 / 0.910 / 0.930.
            EXPECT_GE(car.coverage, sensor.model.numBeams() == 64 ? 0.95 : 0.88);
            EXPECT_GE(car.purity, 0.99);
        }
    }
}

TEST(HardObjects, MovingCarsAcrossTheSweepStart) {
    struct Case {
        const char* name;
        double distance, yaw_deg;
        Eigen::Vector2d velocity;
    };
    for (const Case& c : {Case{"oncoming_15mps_21m", 21.0, 0.0, {-15.0, 0.0}},
                          Case{"crossing_10mps_23m", 23.0, 90.0, {0.0, -10.0}},
                          Case{"receding_8mps_25m", 25.0, 10.0, {7.9, 1.4}},
                          Case{"oncoming_25mps_20m", 20.0, 0.0, {-25.0, 0.0}},
                          Case{"oncoming_25mps_25m", 25.0, 10.0, {-25.0, 0.0}}}) {
        SCOPED_TRACE(c.name);
        const ObjectRun r =
            run(sim::movingCarAcrossSweepStart(c.distance, c.yaw_deg, c.velocity), hdl64());
        const test::ObjectScore car = score(r, 1, c.name);
        // Before: 0.461 (oncoming: its halves 1.5 m apart across the sweep start), 0.971,
        // 0.613 (receding, end on: the rear face and the cabin behind the boot 0.5-0.52 m
        // apart, just beyond T_vert). After seam linkage and range-scaled vertical merges:
        // 0.907, 0.995, 0.930. Oncoming at 25 m/s (halves 2.5 m apart): 0.403 and 0.572 with
        // seam_max_shift 2 m, 0.917 and 0.917 at 3 m.
        EXPECT_GE(car.coverage, 0.88);
        EXPECT_GE(car.purity, 0.99);
    }
}

// ---- Purity (issue 14): objects of different instances side by side or one behind another ----
// Mean coverage and the worst purity of a scene's instances, as the instance evaluator counts
// them (scoreObject); the hdl64 sensor.
struct PurityFigures {
    double coverage = 0, worst_purity = 1;
};

PurityFigures purityOf(const sim::Scene& scene, const std::vector<uint32_t>& ids,
                       const char* what) {
    const ObjectRun r = run(scene, hdl64());
    PurityFigures f;
    for (const uint32_t id : ids) {
        const test::ObjectScore s =
            test::scoreObject(r.scan.gt, r.result.labels, r.result.cluster_id, id);
        f.coverage += s.coverage / double(ids.size());
        f.worst_purity = std::min(f.worst_purity, s.purity);
    }
    std::printf("%-28s coverage %.3f worst purity %.3f\n", what, f.coverage, f.worst_purity);
    return f;
}

// Figures over a grid (distance x gap) before -> after the range-scaled merge at the point's
// range and the see-through depth veto are in docs/parameters.md; the cases here are one per
// scene, the cheapest that show each.
TEST(HardObjects, PurityOfNeighbouringObjects) {
    // Person 0.45 m beside / in front of a car at 20 m, cars parked nose to tail 0.6 m apart at
    // 22 m, a car 0.4 m before a hedge at 20 m: all apart, before and after (coverage 0.999,
    // 0.976, 0.955).
    struct Case {
        sim::Scene scene;
        const char* what;
        std::vector<uint32_t> ids;
        double coverage;
    };
    for (const Case& c :
         {Case{sim::personBesideCar(20.0, 0.45), "person_car_20m_gap0.45", {1, 2, 3}, 0.98},
          Case{sim::parkedCarRow(22.0, 0.6), "car_row_22m_gap0.6", {1, 2, 3, 4}, 0.95},
          Case{sim::carBeforeHedge(20.0, 0.4, 1.8), "car_hedge_20m_gap0.4", {1}, 0.93}}) {
        SCOPED_TRACE(c.what);
        const PurityFigures f = purityOf(c.scene, c.ids, c.what);
        EXPECT_GE(f.coverage, c.coverage);
        EXPECT_GE(f.worst_purity, 0.99);
    }
    // A car parked 1 m behind a car at 15 m, seen through its windows: joined to it by the
    // see-through linkage before (worst purity 0.092); apart once a run seen deeper than
    // see_through_depth behind the gap vetoes the join (1.000).
    const PurityFigures behind =
        purityOf(sim::objectBehindParkedCar(15.0, 1.0, true), {1, 2}, "car_behind_car_15m_gap1.0");
    EXPECT_GE(behind.coverage, 0.97);
    EXPECT_GE(behind.worst_purity, 0.99);
}

// travel-eval merges' diagnostic (eval::mergedParts) on a cluster made by hand: two cars parked
// nose to tail 0.6 m apart at 22 m put in one cluster (cluster ids set here, not clustered). Their
// closest points are on one ring, 0.6 m apart at the same range: beyond T_horz and T_vert (even
// range-scaled), within occlusion_max_gap, so the rule that can join them is the occlusion one.
TEST(HardObjects, MergeDiagnosticNamesTheLinkingRule) {
    const ObjectRun r = run(sim::parkedCarRow(22.0, 0.6), hdl64());
    const std::size_t n = r.scan.gt.size();
    std::vector<uint32_t> labels(n), cluster(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const uint32_t id = r.scan.gt.instance[i];
        labels[i] = id ? (10u | (id << 16)) : r.scan.gt.cls[i] == sim::Ground ? 40u : 0u;
        cluster[i] = id == 2 || id == 3 ? 1 : 0;
    }
    Pipeline pipeline(hdl64().params);  // the object stage the diagnosis reads
    Result result;
    pipeline.process(r.scan.cloud, {}, result);
    const std::vector<eval::MergedPart> parts =
        eval::mergedParts(cluster, labels, r.scan.cloud, pipeline);
    // The cluster's largest GT object owns it; the other car is its largest part (the GT's
    // 0.5 m Euclidean split also cuts window returns off each car: smaller parts).
    ASSERT_FALSE(parts.empty());
    const eval::MergedPart& p = *std::max_element(
        parts.begin(), parts.end(),
        [](const auto& a, const auto& b) { return a.part_points < b.part_points; });
    EXPECT_EQ(p.owner_semantic, 10u);
    EXPECT_EQ(p.part_semantic, 10u);
    EXPECT_FALSE(p.same_label);
    EXPECT_TRUE(p.part_is_object);
    EXPECT_EQ(p.rule, eval::LinkRule::Occlusion) << eval::toString(p.rule);
    EXPECT_NEAR(p.link_distance, 0.6, 0.1);
    EXPECT_LT(p.depth_jump, 0.4f);
    EXPECT_EQ(p.row_gap, 0);
    EXPECT_GT(p.range, 20.f);
    EXPECT_LT(p.range, 26.f);
    EXPECT_GE(test::expectPairsSatisfyTheirRule(parts, cluster, pipeline), 1u);
}

// The diagnosis names pairs that satisfy their rule on what the object stage linked on
// (MergeDiagnosticPairs.hpp), on the 64- and the 128-beam preset (rows from the scan order and from
// the os128 table): parked cars at 20-25 m, every clustered point put in one cluster so that every
// GT object is a part of it.
TEST(HardObjects, MergeDiagnosticPairsSatisfyTheirRule) {
    for (const Sensor& sensor : {hdl64(), os128()}) {
        SCOPED_TRACE(sensor.name);
        const ObjectRun r = run(sim::parkedCarsAt20To25Metres(), sensor);
        const std::size_t n = r.scan.gt.size();
        std::vector<uint32_t> labels(n), cluster(n, 0);
        for (std::size_t i = 0; i < n; ++i) {
            const uint32_t id = r.scan.gt.instance[i];
            labels[i] = id ? (10u | (id << 16)) : r.scan.gt.cls[i] == sim::Ground ? 40u : 0u;
            cluster[i] = r.result.cluster_id[i] != 0;
        }
        Pipeline pipeline(sensor.params);
        Result result;
        pipeline.process(r.scan.cloud, {}, result);
        const std::vector<eval::MergedPart> parts =
            eval::mergedParts(cluster, labels, r.scan.cloud, pipeline);
        const std::size_t checked = test::expectPairsSatisfyTheirRule(parts, cluster, pipeline);
        std::printf("%s: %zu parts, %zu linking pairs checked\n", sensor.name, parts.size(),
                    checked);
        EXPECT_GE(checked, 2u);
    }
}

}  // namespace
}  // namespace travel

namespace travel {
namespace {

// A sedan seen end on (from behind, as a car ahead in its lane) at 20-25 m: the rings over its
// rear face pass above the boot lid (too flat to be hit at this grazing angle) and land on the
// cabin (rear bench, pillars, roof edge) 0.6-1.2 m behind the face, beyond T_vert: the car fell
// in two, the face and the cabin. Set-back linkage joins the cabin to the face it stands on.
// Before: coverage 0.596 / 0.538 at 20 m (paint 1.0 / 0.7), 0.631 / 0.577 at 25 m; after 0.970 /
// 0.979, 0.972 / 0.981. A child (1.2 m) 0.5 or 1 m behind a car seen side on, over the car's
// body: narrower than half the car, it stays apart (0.3 m behind, it is joined before and after
// this rule: an open purity case).
TEST(HardObjects, EndOnCarKeepsItsCabin) {
    for (const double distance : {20.0, 25.0})
        for (const double paint : {1.0, 0.7}) {
            sim::Scene scene;
            scene.boxes = sim::realisticCar(1, {distance, 0.0}, 0.0, paint, paint < 1 ? 0.5 : 1.0);
            char what[64];
            std::snprintf(what, sizeof what, "end_on_%.0fm_paint%.1f", distance, paint);
            const test::ObjectScore car = score(run(scene, hdl64()), 1, what);
            EXPECT_GE(car.coverage, 0.85);
            EXPECT_GE(car.purity, 0.99);
        }
    for (const double gap : {0.5, 1.0}) {
        char what[64];
        std::snprintf(what, sizeof what, "child_behind_car_15m_gap%.1f", gap);
        const PurityFigures f =
            purityOf(sim::objectBehindParkedCar(15.0, gap, false), {1, 2}, what);
        EXPECT_GE(f.worst_purity, 0.99);
    }
}

}  // namespace
}  // namespace travel

namespace travel {
namespace {

// A child (1.2 m) or a car right behind a car seen side on, visible only through its windows:
// the see-through linkage took them for the car's far side (its depth bound, 2.5 m along the
// ray, reaches 0.7 m beyond a car's far side). The width veto (see_through_width) measures the
// depth across the window's frame, in xy, and keeps them apart. Before -> after (worst purity):
// child 0.3 and 0.5 m behind at 20 m 0.016 -> 1.000; a car 0.3 m behind at 15 m 0.094 -> 1.000,
// 0.45 m behind at 12 m 0.083 -> 1.000. A car alone seen at 30
// or 45 degrees at 10 and 20 m keeps its far side (coverage unchanged: the depth across the
// frame is the car's width, whatever the angle).
TEST(HardObjects, ObjectRightBehindACarStaysApart) {
    struct Case {
        double distance, gap;
        bool is_car;
    };
    for (const Case& c : {Case{20.0, 0.3, false}, Case{20.0, 0.5, false}, Case{15.0, 0.3, true},
                          Case{12.0, 0.45, true}}) {
        char what[64];
        std::snprintf(what, sizeof what, "%s_behind_car_%.0fm_gap%.2f", c.is_car ? "car" : "child",
                      c.distance, c.gap);
        const PurityFigures f =
            purityOf(sim::objectBehindParkedCar(c.distance, c.gap, c.is_car), {1, 2}, what);
        EXPECT_GE(f.worst_purity, 0.99);
    }
    for (const double distance : {10.0, 20.0})
        for (const double yaw : {30.0, 45.0}) {
            sim::Scene scene;
            scene.boxes = sim::realisticCar(1, {0.0, distance}, yaw);
            char what[64];
            std::snprintf(what, sizeof what, "car_%.0fm_yaw%.0f", distance, yaw);
            const test::ObjectScore car = score(run(scene, hdl64()), 1, what);
            EXPECT_GE(car.coverage, 0.95);
            EXPECT_GE(car.purity, 0.99);
        }
}

}  // namespace
}  // namespace travel

#include "travel/eval/ObjectMetrics.hpp"

namespace travel {
namespace {

// ---- Purity in urban streets (issue 14): a thing's cluster holding its instance and more ----
// Scenes of SemanticKITTI-like streets (the road along +x, parked cars on its left, centres
// `d` metres from the sensor), scored with the instance evaluator (evaluateObjects: coverage
// and purity of the thing instances, every point of the best cluster counted, ground and stuff
// included), the synthetic ground truth given SemanticKITTI labels: car 10, person 30,
// bicyclist 31 (things), vegetation 70, trunk 71, building 50, pole 80, traffic sign 81 (stuff,
// instance 0), ground 40.
struct StreetScene {
    sim::Scene scene;
    std::map<uint32_t, uint32_t> semantic;  // sim instance -> SemanticKITTI class
};

constexpr uint32_t kCar = 10, kPerson = 30, kBicyclist = 31, kBuilding = 50, kVegetation = 70,
                   kTrunk = 71, kPoleClass = 80, kSign = 81;

void addCar(StreetScene& s, uint32_t id, const Eigen::Vector2d& centre, double yaw_deg = 0.0) {
    const std::vector<sim::Box> parts = sim::realisticCar(id, centre, yaw_deg);
    s.scene.boxes.insert(s.scene.boxes.end(), parts.begin(), parts.end());
    s.semantic[id] = kCar;
}

sim::Box standingBox(uint32_t id, double x, double y, double length, double width, double height,
                     double clearance = 0.0) {
    sim::Box b;
    b.id = id, b.centre = {x, y}, b.length = length, b.width = width, b.height = height;
    b.clearance = clearance;
    return b;
}

// Parked cars nose to tail 0.4-1.0 m apart (sim::parkedCarRow).
StreetScene carRow(double d, double gap) {
    StreetScene s;
    s.scene = sim::parkedCarRow(d, gap);
    for (uint32_t id = 1; id <= 4; ++id) s.semantic[id] = kCar;
    return s;
}

// A street tree on the sidewalk beyond a parked car: trunk (0.15 m radius) `trunk_gap` beyond
// the car's far side, a 4 x 4 m, 2.5 m deep crown from `crown_bottom` up, over the car's far half.
StreetScene carUnderTree(double d, double crown_bottom, double trunk_gap = 0.6) {
    StreetScene s;
    addCar(s, 1, {0.0, d});
    const double trunk_y = d + 0.9 + trunk_gap + 0.15;
    sim::Pole trunk;
    trunk.id = 2, trunk.centre = {0.3, trunk_y}, trunk.radius = 0.15,
    trunk.height = crown_bottom + 0.5;
    s.scene.poles.push_back(trunk);
    s.scene.boxes.push_back(standingBox(3, 0.3, trunk_y, 4.0, 4.0, 2.5, crown_bottom));
    s.semantic[2] = kTrunk, s.semantic[3] = kVegetation;
    return s;
}

// A parked car with a hedge (1 m thick, 1.8 m high, vegetation) or a wall (0.25 m, 2.5 m,
// building) running along its far side `gap` metres away.
StreetScene carBesideHedgeOrWall(double d, double gap, bool wall) {
    StreetScene s;
    addCar(s, 1, {0.0, d});
    sim::Wall w;
    w.id = 2;
    w.thickness = wall ? 0.25 : 1.0;
    w.height = wall ? 2.5 : 1.8;
    const double y = d + 0.9 + gap + 0.5 * w.thickness;
    w.a = {-10.0, y}, w.b = {10.0, y};
    s.scene.walls.push_back(w);
    s.semantic[2] = wall ? kBuilding : kVegetation;
    return s;
}

// A person (0.5 x 0.35 x 1.75 m) `gap` beyond a parked car's front bumper and another `gap` in
// front of its near side (sim::personBesideCar), or a cyclist (1.8 x 0.6 x 1.7 m) riding past
// the car `gap` from its near side.
StreetScene personOrCyclistBesideCar(double d, double gap, bool cyclist) {
    StreetScene s;
    if (!cyclist) {
        s.scene = sim::personBesideCar(d, gap);
        s.semantic = {{1, kCar}, {2, kPerson}, {3, kPerson}};
        return s;
    }
    addCar(s, 1, {0.0, d});
    s.scene.boxes.push_back(standingBox(2, 0.5, d - 0.9 - gap - 0.3, 1.8, 0.6, 1.7));
    s.semantic[2] = kBicyclist;
    return s;
}

// A person `gap` from a street-light pole (0.1 m radius, 4 m high) on the near side of the
// sidewalk, both `d` metres away.
StreetScene personBesidePole(double d, double gap) {
    StreetScene s;
    sim::Pole pole;
    pole.id = 1, pole.centre = {0.0, d}, pole.radius = 0.1, pole.height = 4.0;
    s.scene.poles.push_back(pole);
    s.scene.boxes.push_back(standingBox(2, 0.1 + gap + 0.25, d, 0.5, 0.35, 1.75));
    s.semantic = {{1, kPoleClass}, {2, kPerson}};
    return s;
}

// A sign post (0.04 m radius, 2.6 m) with a 0.6 x 0.6 m plate from 2.0 m up, `gap` beyond a
// parked car's far side (the sidewalk's edge) near its front, or `gap` ahead of its front bumper.
StreetScene carBesideSignPost(double d, double gap, bool ahead) {
    StreetScene s;
    addCar(s, 1, {0.0, d});
    const Eigen::Vector2d post =
        ahead ? Eigen::Vector2d(2.25 + gap + 0.04, d) : Eigen::Vector2d(1.5, d + 0.9 + gap + 0.04);
    sim::Pole p;
    p.id = 2, p.centre = post, p.radius = 0.04, p.height = 2.6;
    s.scene.poles.push_back(p);
    s.scene.boxes.push_back(standingBox(3, post.x(), post.y() - 0.06, 0.6, 0.04, 0.6, 2.0));
    s.semantic = {{1, kCar}, {2, kPoleClass}, {3, kSign}};
    return s;
}

struct StreetFigures {
    double coverage = 0, worst_purity = 1;  // over the scene's thing instances
    std::size_t instances = 0;
};

// HDL-64E 1.73 m up, level or on KITTI's mount (roll 1.6, pitch 0.6 deg, not given to the
// pipeline, as on the dev frames).
StreetFigures streetFigures(const StreetScene& s, bool tilted, const Params& params,
                            bool explain = false) {
    sim::LidarModel model = sim::LidarModel::hdl64();
    model.range_noise_sigma = 0.01;
    model.seed = 7;
    model.max_range = params.max_range;
    const sim::Scan scan = sim::scan(s.scene, model,
                                     sim::sensorPoseAt(s.scene, 0, 0, sim::kSensorHeight,
                                                       tilted ? 1.6 : 0.0, tilted ? 0.6 : 0.0, 0));
    Result result;
    Pipeline pipeline(params);
    pipeline.process(scan.cloud, {}, result);
    std::vector<uint32_t> labels(scan.gt.size(), 0);
    for (std::size_t i = 0; i < labels.size(); ++i) {
        const uint32_t id = scan.gt.instance[i];
        if (scan.gt.cls[i] == sim::Ground) {
            labels[i] = 40;
        } else if (id != 0) {
            const uint32_t semantic = s.semantic.at(id);
            labels[i] = semantic <= 32 ? (semantic | id << 16) : semantic;
        }
    }
    const ObjectScores scores =
        evaluateObjects(result.cluster_id, result.labels, labels, scan.cloud);
    StreetFigures f;
    for (const InstanceScore& i : scores.instances) {
        f.coverage += i.coverage / double(scores.instances.size());
        f.worst_purity = std::min(f.worst_purity, i.purity);
    }
    f.instances = scores.instances.size();
    if (explain && f.worst_purity < 0.99)
        for (const eval::MergedPart& m :
             eval::mergedParts(result.cluster_id, labels, scan.cloud, pipeline))
            std::printf(
                "    part %s in %s: %zu points at %.1f m, %s, link %.2f m, depth jump %.2f, rows "
                "%d\n",
                eval::semanticName(m.part_semantic).c_str(),
                eval::semanticName(m.owner_semantic).c_str(), m.part_points, m.range,
                eval::toString(m.rule), m.link_distance, m.depth_jump, m.row_gap);
    return f;
}

Params streetParams() {
    Params p;
    p.sensor_height = sim::kSensorHeight;
    return p;
}

struct StreetCase {
    const char* kind;
    double distance, gap;
    StreetScene (*make)(double, double);
};

std::vector<StreetCase> streetGrid() {
    std::vector<StreetCase> cases;
    for (const double d : {8.0, 15.0, 22.0}) {
        for (const double gap : {0.4, 0.6, 0.8, 1.0}) cases.push_back({"car_row", d, gap, carRow});
        for (const double bottom : {1.8, 2.2, 2.6})
            cases.push_back({"car_under_tree", d, bottom,
                             [](double dd, double b) { return carUnderTree(dd, b); }});
        for (const double gap : {0.2, 0.4, 0.7}) {
            cases.push_back({"car_hedge", d, gap, [](double dd, double g) {
                                 return carBesideHedgeOrWall(dd, g, false);
                             }});
            cases.push_back({"car_wall", d, gap, [](double dd, double g) {
                                 return carBesideHedgeOrWall(dd, g, true);
                             }});
        }
        for (const double gap : {0.3, 0.45, 0.6}) {
            cases.push_back({"person_car", d, gap, [](double dd, double g) {
                                 return personOrCyclistBesideCar(dd, g, false);
                             }});
            cases.push_back({"cyclist_car", d, gap, [](double dd, double g) {
                                 return personOrCyclistBesideCar(dd, g, true);
                             }});
        }
        for (const double gap : {0.2, 0.35, 0.5})
            cases.push_back({"person_pole", d, gap, personBesidePole});
        for (const double gap : {0.2, 0.4, 0.7}) {
            cases.push_back({"car_signpost_side", d, gap,
                             [](double dd, double g) { return carBesideSignPost(dd, g, false); }});
            cases.push_back({"car_signpost_ahead", d, gap,
                             [](double dd, double g) { return carBesideSignPost(dd, g, true); }});
        }
    }
    return cases;
}

// The whole grid: 84 scenes, level and tilted, 168 scans (about 15 s: run by hand with
// --gtest_also_run_disabled_tests). It prints each scene's figures and, for an impure one, the
// parts of the merged clusters with the rule that can link them (eval::mergedParts). The table
// is in docs/results.md ("Purity in urban streets").
TEST(StreetPurity, DISABLED_Grid) {
    const Params params = streetParams();
    double sum_cov[2] = {}, sum_pur[2] = {};
    for (const StreetCase& c : streetGrid()) {
        const StreetScene s = c.make(c.distance, c.gap);
        for (const bool tilted : {false, true}) {
            const StreetFigures f = streetFigures(s, tilted, params, true);
            std::printf("%-20s d %4.1f gap %.2f %-6s coverage %.3f worst purity %.3f (%zu)\n",
                        c.kind, c.distance, c.gap, tilted ? "tilted" : "level", f.coverage,
                        f.worst_purity, f.instances);
            sum_cov[tilted] += f.coverage, sum_pur[tilted] += f.worst_purity;
            EXPECT_GT(f.instances, 0u);
        }
    }
    const double n = double(streetGrid().size());
    std::printf("mean coverage level %.4f tilted %.4f, mean worst purity level %.4f tilted %.4f\n",
                sum_cov[0] / n, sum_cov[1] / n, sum_pur[0] / n, sum_pur[1] / n);
}

// One scene of each kind that stays apart today, at the distance where it is closest to joining,
// on one mount each (level or KITTI's tilt; both give the same verdicts on these scenes): each
// thing instance keeps its cluster to itself (worst purity >= 0.99; 1.000 on both mounts now)
// and the scene's mean coverage is >= 0.90 (0.916-0.967 now). The joins the grid shows (a car
// 0.2-0.4 m before a hedge or a wall at 8 m, a person 0.3 m from a car at 8 m, cars 0.4 m apart,
// a person 0.2 m from a pole) are the open purity cases of docs/results.md.
TEST(StreetPurity, ObjectsThatStayApart) {
    const Params params = streetParams();
    struct Case {
        const char* what;
        StreetScene scene;
        bool tilted;
    };
    for (const Case& c :
         {Case{"car_row_8m_gap0.6", carRow(8.0, 0.6), false},
          Case{"car_wall_8m_gap0.7", carBesideHedgeOrWall(8.0, 0.7, true), true},
          Case{"car_hedge_15m_gap0.2", carBesideHedgeOrWall(15.0, 0.2, false), true},
          Case{"person_car_8m_gap0.45", personOrCyclistBesideCar(8.0, 0.45, false), false},
          Case{"person_pole_15m_gap0.35", personBesidePole(15.0, 0.35), true},
          Case{"car_under_tree_15m_crown1.8", carUnderTree(15.0, 1.8), false},
          Case{"car_signpost_15m_gap0.2", carBesideSignPost(15.0, 0.2, false), true}}) {
        SCOPED_TRACE(c.what);
        const StreetFigures f = streetFigures(c.scene, c.tilted, params);
        std::printf("%-28s %-6s coverage %.3f worst purity %.3f\n", c.what,
                    c.tilted ? "tilted" : "level", f.coverage, f.worst_purity);
        EXPECT_GE(f.instances, 1u);
        EXPECT_GE(f.coverage, 0.90);
        EXPECT_GE(f.worst_purity, 0.99);
    }
}

}  // namespace
}  // namespace travel
