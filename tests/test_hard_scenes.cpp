// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// The failures seen on scans the project was never tuned on (issue 14), each reproduced in a
// synthetic scene with exact ground truth: fence and wall bases labelled ground, grass verges
// missed, an uneven off-road meadow with bushes and trunks, a car right beside the sensor.
// Each test prints its figures (run with --gtest_filter=HardScenes.* to see them) and asserts
// the level the current algorithm reaches, with margin: a change that loses it fails here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "SceneMetrics.hpp"
#include "travel/Pipeline.hpp"
#include "travel/sim/Scenes.hpp"
#include "travel/sim/SyntheticLidar.hpp"

namespace travel {
namespace {

struct SceneRun {
    sim::Scan scan;
    Result result;
    test::SceneScores scores;
};

SceneRun segment(const sim::Scene& scene, sim::LidarModel model, const Params& params,
                 double height) {
    model.range_noise_sigma = 0.01;
    model.seed = 7;
    model.max_range = params.max_range;
    SceneRun run;
    run.scan = sim::scan(scene, model, sim::sensorPoseAt(scene, 0, 0, height, 0, 0, 0));
    Pipeline pipeline(params);
    pipeline.process(run.scan.cloud, {}, run.result);
    run.scores = test::scoreScene(run.scan.gt, run.result.labels);
    return run;
}

// Non-ground points of objects with instance in [lo, hi] labelled ground, and their number.
std::pair<std::size_t, std::size_t> objectPointsAsGround(const SceneRun& run, uint32_t lo,
                                                         uint32_t hi) {
    std::size_t as_ground = 0, total = 0;
    for (std::size_t i = 0; i < run.scan.gt.size(); ++i) {
        const uint32_t id = run.scan.gt.instance[i];
        if (id < lo || id > hi) continue;
        ++total;
        as_ground += run.result.labels[i] == PointClass::Ground;
    }
    return {as_ground, total};
}

void print(const char* name, const test::SceneScores& s) {
    std::printf("%-28s ground P %.4f R %.4f F1 %.4f (fp %zu fn %zu, > 0.3 m as ground %zu)\n", name,
                s.precision(), s.recall(), s.f1(), s.fp, s.fn, s.high_obstacle_as_ground);
}

Params hdl64Params() {
    Params p;
    p.sensor_height = sim::kSensorHeight;
    return p;
}

// With the face rule as the os64 preset sets it (off by default, see docs/parameters.md).
Params faceParams() {
    Params p = hdl64Params();
    p.vertical_face_min_rise = 0.25;
    p.vertical_face_min_length = 0.0;  // under every ground point
    return p;
}

// With the face rule scoped to walls and fences (vertical_face_min_length 6 m), its road scope.
Params wallParams() {
    Params p = hdl64Params();
    p.vertical_face_min_rise = 0.25;
    return p;
}

// The face rule with the feet clustered and a foot height of 0.08 m (the smallest that keeps the
// SemanticKITTI dev purity at 0.990, docs/parameters.md "Off-road driving"; not a default): feet
// within 0.08 m of their ground plane stay ground.
Params roadFaceParams() {
    Params p = faceParams();
    p.cluster_face_feet = true;
    p.vertical_face_min_foot_height = 0.08;
    return p;
}

// OS1-64 (uniform +-16.6 deg, 64 x 2048), as share/presets/os64.yaml, at 1.3 m.
Params os64Params() {
    Params p;
    p.sensor_height = sim::kOffRoadSensorHeight;
    p.min_range = 0.5;
    p.max_range = 60.0;
    p.num_rings = 64;
    p.num_columns = 2048;
    p.elevation_table = "uniform";
    p.min_elevation_deg = -16.6;
    p.max_elevation_deg = 16.6;
    p.vertical_face_min_rise = 0.25;
    p.vertical_face_min_length = 0.0;
    p.cluster_face_feet = true;
    return p;
}

// A sensor and its mount for the scenes seen by several sensors.
struct Sensor {
    const char* name;
    sim::LidarModel model;
    Params params;
    double height;
};

Sensor os64Sensor() {
    return {"os64", sim::LidarModel::uniform(64, -16.6, 16.6, 2048), os64Params(),
            sim::kOffRoadSensorHeight};
}

// The same with the road scope of the face rule (walls and fences only).
Sensor os64WallsSensor() {
    Sensor s = os64Sensor();
    s.name = "os64_walls";
    s.params.vertical_face_min_length = wallParams().vertical_face_min_length;
    return s;
}

// `scene` seen by `sensor`: prints its scores and the points of two groups of objects
// (instances [lo, hi]) labelled ground; returns the run and the two (as ground, total) pairs.
struct GroupsAsGround {
    SceneRun run;
    std::pair<std::size_t, std::size_t> first, second;
};
GroupsAsGround segmentGroups(const char* scene_name, const sim::Scene& scene, const Sensor& sensor,
                             const char* first_name, uint32_t first_lo, uint32_t first_hi,
                             const char* second_name, uint32_t second_lo, uint32_t second_hi) {
    GroupsAsGround g{segment(scene, sensor.model, sensor.params, sensor.height), {}, {}};
    std::printf("%s_%-16s", scene_name, sensor.name);
    print("", g.run.scores);
    g.first = objectPointsAsGround(g.run, first_lo, first_hi);
    g.second = objectPointsAsGround(g.run, second_lo, second_hi);
    std::printf("  %s points as ground %zu / %zu, %s %zu / %zu\n", first_name, g.first.first,
                g.first.second, second_name, g.second.first, g.second.second);
    return g;
}

TEST(HardScenes, FenceAndWallBasesBesideARoad) {
    // Face rule off: F1 0.977, fence points as ground 1194 / 20514.
    const SceneRun run =
        segment(sim::fencesAndWalls(), sim::LidarModel::hdl64(), faceParams(), sim::kSensorHeight);
    print("fences_walls", run.scores);
    const auto fence = objectPointsAsGround(run, 1, 199);
    const auto wall = objectPointsAsGround(run, 200, 201);
    std::printf("  fence points as ground %zu / %zu, wall+footing %zu / %zu\n", fence.first,
                fence.second, wall.first, wall.second);
    EXPECT_GE(run.scores.f1(), 0.982);  // 0.985
    EXPECT_EQ(run.scores.high_obstacle_as_ground, 0u);
    // The lowest centimetres of the mesh (5.8 % of the fence without the face rule; 3 points
    // with it). Not fixed: the lowest 0.17 m of the footing's front face (4.3 % of wall +
    // footing): the footing is 0.3 m high and its flat top (0.175 m deep before the wall)
    // breaks the steep climb, so those points rise less than 0.25 m up to it.
    EXPECT_LE(fence.first, 10u);
    EXPECT_LE(wall.first, 0.05 * wall.second);
}

// Mesh fences (rays pass between the wires, 30 % of those hitting one are lost) and walls with
// and without footings on rough grass verges, from an HDL-64E 1.73 m up (KITTI defaults, face
// rule off; and with it) and an OS1-64 1.3 m up (os64). The lost returns leave empty rings in a
// wire's column: the face rule's climb steps over up to vertical_face_max_gap (2) of them.
TEST(HardScenes, MeshFencesAndWallsOnRoughVerges) {
    struct Case {
        Sensor sensor;
        double min_f1;
        std::size_t max_fence_as_ground, max_walls_as_ground, max_high_as_ground;
    };
    // Measured (vertical_face_max_gap 0 -> 2): hdl64 (the road default, no face rule) F1
    // 0.9823, precision 0.9785, fence as ground 329 / 6313, walls 1706 / 16099; hdl64_walls
    // (the face rule under clusters with a 6 m side) F1 0.9897, precision 0.9950, fence 72,
    // walls 390; os64_walls (that scope on an OS1-64) F1 0.9959, fence 37 / 4184, walls 6;
    // hdl64_faces F1 0.9893 -> 0.9899, precision 0.9935 -> 0.9956, fence 216 -> 27, walls 386 (the
    // footing's front: its top breaks the climb, see FenceAndWallBasesBesideARoad); os64 F1 0.9951
    // -> 0.9961, precision 0.9966 -> 0.9996, fence 175 -> 18, walls 9 -> 6. hdl64_foot (the face
    // rule with vertical_face_min_foot_height 0.08, feet clustered): F1 0.9855, precision 0.9849,
    // fence 180, walls 1241: the floor gives back most of the rule's fix (the lowest 8 cm of each
    // face stay ground).
    for (const Case& c :
         {Case{{"hdl64", sim::LidarModel::hdl64(), hdl64Params(), sim::kSensorHeight},
               0.978,
               450,
               2000,
               2},
          Case{{"hdl64_walls", sim::LidarModel::hdl64(), wallParams(), sim::kSensorHeight},
               0.987,
               110,
               500,
               0},
          Case{{"hdl64_faces", sim::LidarModel::hdl64(), faceParams(), sim::kSensorHeight},
               0.987,
               60,
               450,
               0},
          Case{{"hdl64_foot", sim::LidarModel::hdl64(), roadFaceParams(), sim::kSensorHeight},
               0.984,
               220,
               1400,
               0},
          Case{os64Sensor(), 0.994, 40, 15, 0}, Case{os64WallsSensor(), 0.994, 60, 40, 0}}) {
        const GroupsAsGround g =
            segmentGroups("mesh_fences", sim::meshFencesOnRoughVerges(), c.sensor, "fence", 1, 112,
                          "walls+footing", 200, 202);
        SCOPED_TRACE(c.sensor.name);
        EXPECT_GE(g.run.scores.f1(), c.min_f1);
        EXPECT_LE(g.first.first, c.max_fence_as_ground);
        EXPECT_LE(g.second.first, c.max_walls_as_ground);
        EXPECT_LE(g.run.scores.high_obstacle_as_ground, c.max_high_as_ground);
    }
}

// Every point of a cluster is counted in its summary, which bounds them all.
void expectSummariesMatchIds(const Result& result, const AlignedCloud& aligned) {
    std::vector<uint32_t> count(result.clusters.size(), 0);
    for (std::size_t i = 0; i < result.cluster_id.size(); ++i) {
        const uint32_t id = result.cluster_id[i];
        if (id == 0) continue;
        ASSERT_LE(id, result.clusters.size());
        ++count[id - 1];
        const ClusterSummary& c = result.clusters[id - 1];
        const Eigen::Vector3f p(aligned.x[i], aligned.y[i], aligned.z[i]);
        EXPECT_TRUE((p.array() >= c.aabb_min.array()).all() &&
                    (p.array() <= c.aabb_max.array()).all())
            << "point " << i << " outside the box of cluster " << id;
        EXPECT_GE(c.first_point, 0u);
        EXPECT_LE(c.first_point, i);
    }
    for (std::size_t k = 0; k < result.clusters.size(); ++k)
        EXPECT_EQ(result.clusters[k].num_points, count[k]) << "cluster " << k + 1;
}

TEST(HardScenes, FaceFeetJoinTheClusterOfTheirFace) {
    // cluster_face_feet: the feet the face rule unlabels join their face's cluster (they take
    // no part in the run merging). Without it they stay unclustered.
    Params params = faceParams();
    sim::LidarModel model = sim::LidarModel::hdl64();
    model.range_noise_sigma = 0.01, model.seed = 7, model.max_range = params.max_range;
    const sim::Scan scan =
        sim::scan(sim::fencesAndWalls(), model,
                  sim::sensorPoseAt(sim::fencesAndWalls(), 0, 0, sim::kSensorHeight, 0, 0, 0));
    Result apart, joined;
    Pipeline(params).process(scan.cloud, {}, apart);
    params.cluster_face_feet = true;
    Pipeline pipeline(params);
    pipeline.process(scan.cloud, {}, joined);
    ASSERT_EQ(apart.labels, joined.labels);  // clustering only
    // Each object's id: the cluster of most of its non-foot points.
    std::map<uint32_t, std::map<uint32_t, std::size_t>> votes;
    std::size_t feet = 0;
    for (std::size_t i = 0; i < scan.gt.size(); ++i) {
        if (joined.labels[i] != PointClass::NonGround || scan.gt.instance[i] == 0) continue;
        if (apart.cluster_id[i] == 0) continue;
        ++votes[scan.gt.instance[i]][joined.cluster_id[i]];
    }
    std::size_t wrong = 0;
    for (std::size_t i = 0; i < scan.gt.size(); ++i) {
        const uint32_t object = scan.gt.instance[i];
        // A foot: non-ground, and unclustered only without cluster_face_feet.
        if (joined.labels[i] != PointClass::NonGround || apart.cluster_id[i] != 0 || object == 0)
            continue;
        ++feet;
        uint32_t face_id = 0;
        std::size_t best = 0;
        for (const auto& [id, n] : votes[object])
            if (n > best) best = n, face_id = id;
        wrong += joined.cluster_id[i] == 0 || joined.cluster_id[i] != face_id;
    }
    std::printf("face feet %zu, not in their object's cluster %zu\n", feet, wrong);
    EXPECT_GT(feet, 1000u);  // the fence mesh's and the footing's lowest rows
    EXPECT_EQ(wrong, 0u);
    expectSummariesMatchIds(joined, pipeline.aligned());
}

TEST(HardScenes, FaceRuleKeepsKerbsAndStepsGround) {
    // 0.15 m kerbs under raised sidewalks and 0.15 m steps (0.4 m deep): ground in the truth
    // (and in SemanticKITTI). A 0.25 m rise is above them: the rule unlabels none.
    Params off = hdl64Params();
    off.vertical_face_min_rise = 0.0;
    const SceneRun with_rule =
        segment(sim::kerbsAndSteps(), sim::LidarModel::hdl64(), faceParams(), sim::kSensorHeight);
    const SceneRun without =
        segment(sim::kerbsAndSteps(), sim::LidarModel::hdl64(), off, sim::kSensorHeight);
    std::size_t unlabelled = 0;
    for (std::size_t i = 0; i < with_rule.result.labels.size(); ++i)
        unlabelled += with_rule.result.labels[i] != without.result.labels[i];
    EXPECT_EQ(unlabelled, 0u);
}

// On roads the face rule is scoped to walls and fences (vertical_face_min_length 6 m):
// cars, people and kerbs are never under a cluster with a 6 m side, so their labels are the
// labels without the rule; a hedge behind a car and the walls lose their feet (with the ground
// just before them), the car keeps its road.
TEST(HardScenes, WallScopeLeavesCarsPeopleAndKerbsAlone) {
    Params off = hdl64Params();
    off.vertical_face_min_rise = 0.0;
    struct Case {
        const char* name;
        sim::Scene scene;
        uint32_t car_lo, car_hi;  // instances of the cars and people (none: 1, 0)
    };
    for (const Case& c : {Case{"kerbs_steps", sim::kerbsAndSteps(), 1, 0},
                          Case{"urban_objects", sim::urbanObjects(), 1, 3},
                          Case{"person_beside_car", sim::personBesideCar(6.0, 0.5), 1, 3},
                          Case{"parked_car_row_1m", sim::parkedCarRow(6.0, 1.0), 1, 4},
                          Case{"car_before_hedge", sim::carBeforeHedge(6.0, 1.0, 1.5), 1, 1}}) {
        SCOPED_TRACE(c.name);
        const SceneRun walls =
            segment(c.scene, sim::LidarModel::hdl64(), wallParams(), sim::kSensorHeight);
        const SceneRun without =
            segment(c.scene, sim::LidarModel::hdl64(), off, sim::kSensorHeight);
        // Feet taken: true ground (must be none), car and people points, other objects.
        std::size_t ground_taken = 0, car_feet = 0, other_feet = 0;
        for (std::size_t i = 0; i < walls.result.labels.size(); ++i) {
            if (walls.result.labels[i] == without.result.labels[i]) continue;
            const uint32_t id = walls.scan.gt.instance[i];
            if (walls.scan.gt.cls[i] == sim::Ground)
                ++ground_taken;
            else if (id >= c.car_lo && id <= c.car_hi)
                ++car_feet;
            else
                ++other_feet;
        }
        std::printf("%-20s feet: true ground %zu, cars and people %zu, other objects %zu\n", c.name,
                    ground_taken, car_feet, other_feet);
        // The ground just before a wall's foot, within the height of the wall's lowest hit
        // (the climb from it is steep): measured 26 / 357 feet (urban objects), 52 / 499
        // (hedge).
        EXPECT_LE(ground_taken, 0.12 * other_feet);
        EXPECT_EQ(car_feet, 0u);
    }
}

// The walls scope finds its walls among the object clusters: without cluster_objects it still
// builds them (and reports none), so the labels are those with cluster_objects.
TEST(HardScenes, WallScopeLabelsDoNotDependOnClusterObjects) {
    Params off = wallParams();
    off.vertical_face_min_rise = 0.0;
    Params ground_only = wallParams();
    ground_only.cluster_objects = false;
    const SceneRun walls =
        segment(sim::fencesAndWalls(), sim::LidarModel::hdl64(), wallParams(), sim::kSensorHeight);
    const SceneRun without =
        segment(sim::fencesAndWalls(), sim::LidarModel::hdl64(), off, sim::kSensorHeight);
    const SceneRun no_clusters =
        segment(sim::fencesAndWalls(), sim::LidarModel::hdl64(), ground_only, sim::kSensorHeight);
    std::size_t feet = 0;
    for (std::size_t i = 0; i < walls.result.labels.size(); ++i)
        feet += walls.result.labels[i] != without.result.labels[i];
    EXPECT_GT(feet, 500u);  // the fences' and walls' feet (the scope is on)
    EXPECT_EQ(no_clusters.result.labels, walls.result.labels);
    EXPECT_EQ(no_clusters.result.class_counts, walls.result.class_counts);
    EXPECT_TRUE(no_clusters.result.clusters.empty());
    EXPECT_EQ(
        std::count(no_clusters.result.cluster_id.begin(), no_clusters.result.cluster_id.end(), 0u),
        static_cast<std::ptrdiff_t>(no_clusters.result.cluster_id.size()));
}

// The walls scope takes a foot only under a thin face (vertical_face_max_thickness): half of the
// face's returns within that of their median xy range, so that a hedge, which scatters its
// returns through its depth, keeps its feet (SemanticKITTI: vegetation, ground in protocol A;
// the synthetic LiDAR has no rays passing into foliage, see docs/parameters.md for the dev
// frames' figures). Fences, walls and walls on footings are thin: they lose their feet as without
// the test.
TEST(HardScenes, WallScopeThicknessTestKeepsFenceAndWallFeet) {
    Params off = wallParams(), thin_only = wallParams(), any_face = wallParams();
    off.vertical_face_min_rise = 0.0;
    any_face.vertical_face_max_thickness = 0.0;
    const SceneRun without =
        segment(sim::fencesAndWalls(), sim::LidarModel::hdl64(), off, sim::kSensorHeight);
    const auto feetOf = [&](const Params& with) {
        const SceneRun on =
            segment(sim::fencesAndWalls(), sim::LidarModel::hdl64(), with, sim::kSensorHeight);
        std::size_t feet = 0;
        for (std::size_t i = 0; i < on.result.labels.size(); ++i)
            feet += on.scan.gt.instance[i] != 0 && on.result.labels[i] != without.result.labels[i];
        return feet;
    };
    const std::size_t thin = feetOf(thin_only), any = feetOf(any_face);
    std::printf("fence and wall feet taken: thin faces only %zu, any face %zu\n", thin, any);
    EXPECT_GT(any, 1000u);
    EXPECT_GE(static_cast<double>(thin), 0.98 * static_cast<double>(any));
}

TEST(HardScenes, FaceRuleIgnoresInvalidPoints) {
    // Invalid points have no range-image cell: they change nothing in the face rule.
    const Params params = faceParams();
    const SceneRun run =
        segment(sim::fencesAndWalls(), sim::LidarModel::hdl64(), params, sim::kSensorHeight);
    const PointCloud& clean = run.scan.cloud;
    PointCloud dirty;  // every 7th point preceded by an invalid (NaN) one, rings kept
    std::vector<int> origin;
    for (std::size_t i = 0; i < clean.size(); ++i) {
        if (i % 7 == 0) {
            dirty.push_back(std::nanf(""), 0.f, 0.f);
            dirty.ring.push_back(clean.ring[i]);
            origin.push_back(-1);
        }
        dirty.push_back(clean.x[i], clean.y[i], clean.z[i], clean.intensity[i]);
        dirty.ring.push_back(clean.ring[i]);
        origin.push_back(static_cast<int>(i));
    }
    Pipeline pipeline(params);
    Result result;
    pipeline.process(dirty, {}, result);
    std::size_t differ = 0;
    for (std::size_t k = 0; k < dirty.size(); ++k)
        if (origin[k] >= 0) differ += result.labels[k] != run.result.labels[origin[k]];
    EXPECT_EQ(differ, 0u);
}

TEST(HardScenes, GrassVergesAndEmbankmentsAreGround) {
    const SceneRun run =
        segment(sim::grassVerges(), sim::LidarModel::hdl64(), hdl64Params(), sim::kSensorHeight);
    print("grass_verges", run.scores);
    // TTMF's corner averaging left the verges 0.13-0.3 m above the refitted planes: recall
    // 0.964, F1 0.974. Labelling against the own planes of clear reached nodes: 0.986; against
    // clear neighbours' planes too (nodes straddling the embankment top): 0.994; and the nodes
    // too sparse for a plane (far rings): 0.998, F1 0.990. The false ground (fp ~2000) is the
    // embankment's own rough surface where the 3 cm roughness makes it locally steeper than
    // 25 deg (ground truth NonGround, instance 0).
    EXPECT_GE(run.scores.recall(), 0.995);
    EXPECT_GE(run.scores.f1(), 0.987);
    EXPECT_EQ(run.scores.high_obstacle_as_ground, 0u);
}

// Verges farther out (the dev frames' second case: terrain missed mostly 10-40 m away): a
// straight road with a verge rising 0.3 m over 1 m at 10 m on the left and at 22 m on the
// right, 3 cm roughness. Scored on the points 8-40 m away.
TEST(HardScenes, VergesAt10And22MetresAreGround) {
    sim::Scene scene;
    sim::Ramp left;
    left.start = {0.0, 10.0};
    left.direction = {0.0, 1.0};
    left.length = 1.0;
    left.width = 400.0;
    left.slope_deg = std::atan(0.3 / 1.0) / sim::kDegToRad;
    sim::Ramp right = left;
    right.start = {0.0, -22.0};
    right.direction = {0.0, -1.0};
    scene.ramps = {left, right};
    scene.roughness.amplitude = 0.03;
    scene.roughness.wavelength = 1.0;
    const SceneRun run =
        segment(scene, sim::LidarModel::hdl64(), hdl64Params(), sim::kSensorHeight);
    sim::GroundTruth scored = run.scan.gt;  // points outside 8-40 m left unscored
    for (std::size_t i = 0; i < scored.size(); ++i) {
        const float r = std::hypot(run.scan.cloud.x[i], run.scan.cloud.y[i]);
        if (r < 8.f || r > 40.f) scored.cls[i] = sim::NoReturn;
    }
    const test::SceneScores s = test::scoreScene(scored, run.result.labels);
    print("verges_10_22m", s);
    // Refitted planes only: recall 0.9916 (451 verge points missed), F1 0.9929; with the own
    // and neighbour planes of clear nodes: recall 1.0000, F1 0.9970 (the false ground is the
    // slopes' rough surface where it is locally steeper than 25 deg, as above: 309 -> 321).
    EXPECT_GE(s.recall(), 0.998);
    EXPECT_GE(s.f1(), 0.995);
    EXPECT_EQ(s.high_obstacle_as_ground, 0u);
}

// Verges with sign posts and tree trunks on them (sim::vergesWithStreetFurniture): every verge
// node holds a point 0.5 m or more above its plane, so the clear-node rule alone leaves the
// verge to TTMF's road-level planes. Verge points (terrain 6 cm or more above the road) by
// distance, HDL-64E level and on KITTI's tilted mount (roll 1.6, pitch 0.6 deg, not given to
// the pipeline, as on the dev frames), with the clear-node rule only (clearance_radius 0) and
// with local clearance (the default).
struct VergeFigures {
    double recall[3];  // verge points 0-10, 10-20, 20-40 m away labelled ground
    std::size_t missed[3];
    std::size_t objects_as_ground;  // post and trunk points
    test::SceneScores all;
};

VergeFigures vergeFigures(const sim::Scene& scene, const Eigen::Isometry3d& pose,
                          const sim::Scan& scan, const Params& params) {
    Result result;
    Pipeline(params).process(scan.cloud, {}, result);
    VergeFigures f{};
    std::size_t verge[3] = {};
    for (std::size_t i = 0; i < scan.gt.size(); ++i) {
        const bool ground = result.labels[i] == PointClass::Ground;
        f.objects_as_ground += scan.gt.instance[i] != 0 && ground;
        if (scan.gt.cls[i] != sim::Ground) continue;
        const Eigen::Vector3d p =
            pose * Eigen::Vector3d(scan.cloud.x[i], scan.cloud.y[i], scan.cloud.z[i]);
        if (scene.terrainHeight(p.x(), p.y()) < 0.06) continue;  // the road
        const double r = std::hypot(p.x(), p.y());
        const int bin = r < 10.0 ? 0 : r < 20.0 ? 1 : r < 40.0 ? 2 : -1;
        if (bin < 0) continue;
        ++verge[bin];
        f.missed[bin] += !ground;
    }
    for (int b = 0; b < 3; ++b) f.recall[b] = 1.0 - double(f.missed[b]) / double(verge[b]);
    f.all = test::scoreScene(scan.gt, result.labels);
    return f;
}

TEST(HardScenes, VergesWithPostsAndTreesAreGround) {
    const sim::Scene scene = sim::vergesWithStreetFurniture();
    Params node_rule = hdl64Params();
    node_rule.clearance_radius = 0.0;
    struct Mount {
        const char* name;
        double roll_deg, pitch_deg;
    };
    for (const Mount& mount : {Mount{"level", 0.0, 0.0}, Mount{"tilted", 1.6, 0.6}}) {
        sim::LidarModel model = sim::LidarModel::hdl64();
        model.range_noise_sigma = 0.01;
        model.seed = 7;
        model.max_range = 80.0;
        const Eigen::Isometry3d pose =
            sim::sensorPoseAt(scene, 0, 0, sim::kSensorHeight, mount.roll_deg, mount.pitch_deg, 0);
        const sim::Scan scan = sim::scan(scene, model, pose);
        VergeFigures node{};
        for (const bool local : {false, true}) {
            const VergeFigures f =
                vergeFigures(scene, pose, scan, local ? hdl64Params() : node_rule);
            std::printf(
                "verges_furniture_%s_%-6s verge recall 0-10 m %.4f (%zu missed), 10-20 m "
                "%.4f (%zu), 20-40 m %.4f (%zu); post and trunk points as ground %zu\n",
                mount.name, local ? "local" : "node", f.recall[0], f.missed[0], f.recall[1],
                f.missed[1], f.recall[2], f.missed[2], f.objects_as_ground);
            print("  all points", f.all);
            if (!local) {
                node = f;
                continue;
            }
            // Clear-node rule only: level 0.9560 / 0.9873 / 0.9859, tilted 0.9553 / 0.9873 /
            // 0.9906. Local clearance (0.5 m): level 0.9862 / 0.9971 / 0.9987, tilted 0.9833 /
            // 0.9969 / 0.9962; no post or trunk point more as ground. (The false ground is the
            // embankment's rough surface where it is locally steeper than 25 deg, as above.)
            EXPECT_GE(f.recall[0], 0.98) << mount.name;
            EXPECT_GE(f.recall[1], 0.995) << mount.name;
            EXPECT_GE(f.recall[2], 0.995) << mount.name;
            EXPECT_LE(f.objects_as_ground, node.objects_as_ground) << mount.name;
            EXPECT_LE(f.all.high_obstacle_as_ground, node.all.high_obstacle_as_ground)
                << mount.name;
        }
    }
}

TEST(HardScenes, OffRoadMeadowWithBushesAndTrunks) {
    const SceneRun run =
        segment(sim::offRoadMeadow(), sim::LidarModel::uniform(64, -16.6, 16.6, 2048), os64Params(),
                sim::kOffRoadSensorHeight);
    print("offroad_meadow_os64", run.scores);
    const auto bushes = objectPointsAsGround(run, 1, 8);
    const auto trunks = objectPointsAsGround(run, 11, 16);
    std::printf("  bush points as ground %zu / %zu, trunk %zu / %zu\n", bushes.first, bushes.second,
                trunks.first, trunks.second);
    // Face rule 0.25 m (os64 preset). Without it: precision 0.991, 402 bush and 113 trunk points
    // as ground. With it: F1 0.9946, precision 1.000, 2 bush points; stepping over rings without
    // a return (vertical_face_max_gap 2): F1 0.9992, 0 bush points.
    EXPECT_GE(run.scores.f1(), 0.99);
    EXPECT_GE(run.scores.precision(), 0.999);
    EXPECT_LE(bushes.first + trunks.first, 10u);
    // cluster_face_feet (os64): the feet join their bush or trunk, no non-ground object point
    // is left unclustered.
    std::size_t unclustered = 0;
    for (std::size_t i = 0; i < run.scan.gt.size(); ++i)
        unclustered += run.scan.gt.instance[i] != 0 &&
                       run.result.labels[i] == PointClass::NonGround &&
                       run.result.cluster_id[i] == 0;
    std::printf("  non-ground bush and trunk points without a cluster %zu\n", unclustered);
    EXPECT_EQ(unclustered, 0u);
}

// The meadow on a rough hillside: from x = 3 m the ground rises 8 deg along +x for 25 m (then
// flat), so bushes and trunks stand on slopes, with the bumps and 5 cm roughness on top; the
// bushes are foliage: 30 % of the rays that hit them give no return. Seen by the OS1-64 1.3 m
// up (os64) and by an HDL-64E 1.73 m up with the face rule. Measured (vertical_face_max_gap
// 0 -> 2): os64 precision 0.9953 -> 0.9981, bush and trunk points as ground 205 -> 23, points
// > 0.3 m above the ground as ground 9 -> 3; hdl64 with the face rule 0.9958 -> 0.9981, 341 -> 73.
TEST(HardScenes, BushesAndTrunksOnARoughHillside) {
    sim::Scene scene = sim::offRoadMeadow();
    sim::Ramp hill;
    hill.start = {3.0, 0.0};
    hill.direction = {1.0, 0.0};
    hill.length = 25.0;
    hill.width = 400.0;
    hill.slope_deg = 8.0;
    scene.ramps.push_back(hill);
    for (sim::Box& bush : scene.boxes) bush.return_fraction = 0.7;  // foliage
    struct Case {
        Sensor sensor;
        std::size_t max_objects_as_ground, max_high_as_ground;
    };
    Params hdl = faceParams();
    hdl.cluster_face_feet = true;
    for (const Case& c :
         {Case{os64Sensor(), 40, 5},
          Case{{"hdl64_faces", sim::LidarModel::hdl64(), hdl, sim::kSensorHeight}, 120, 0}}) {
        const GroupsAsGround g =
            segmentGroups("hillside_meadow", scene, c.sensor, "bush", 1, 8, "trunk", 11, 16);
        SCOPED_TRACE(c.sensor.name);
        EXPECT_GE(g.run.scores.precision(), 0.997);
        EXPECT_GE(g.run.scores.f1(), 0.994);
        EXPECT_LE(g.first.first + g.second.first, c.max_objects_as_ground);
        EXPECT_LE(g.run.scores.high_obstacle_as_ground, c.max_high_as_ground);
    }
}

// ---- Harsher off-road scenes: grass, fences with wires, ditches, ruts, puddles, rocks, slopes.
// Grass is ground (SemanticKITTI's terrain), bushes, shrubs, rocks, posts and wires are not;
// mirrored returns below the puddles are not scored (SemanticKITTI marks them outliers).

// Where the OS1-64 stands: `height` above the terrain along the normal of the vehicle's
// footprint (4 x 2 m, heading `yaw_deg`), tilted on its mount by `mount_pitch_deg`.
Eigen::Isometry3d vehicleSensorPose(const sim::Scene& scene, double yaw_deg, double mount_pitch_deg,
                                    double height) {
    const std::vector<Eigen::Vector2d> footprint = {
        {2.0, 1.0}, {2.0, -1.0}, {-2.0, 1.0}, {-2.0, -1.0}};
    double z = 0.0;
    const Eigen::Matrix3d vehicle =
        sim::robotAttitudeOnTerrain(scene, footprint, 0.0, 0.0, yaw_deg * sim::kDegToRad, z);
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() =
        vehicle * Eigen::AngleAxisd(mount_pitch_deg * sim::kDegToRad, Eigen::Vector3d::UnitY());
    pose.translation() = Eigen::Vector3d(0.0, 0.0, z) + vehicle * Eigen::Vector3d(0, 0, height);
    return pose;
}

struct OffRoadRun {
    SceneRun run;
    Eigen::Isometry3d pose;
};

// `scene` seen by the OS1-64 (os64 preset) from `pose`; the attitude (roll and pitch of the
// pose) is given to the pipeline, as an IMU would.
OffRoadRun segmentOffRoad(const sim::Scene& scene, const Eigen::Isometry3d& pose,
                          const Params& params = os64Params()) {
    sim::LidarModel model = sim::LidarModel::uniform(64, -16.6, 16.6, 2048);
    model.range_noise_sigma = 0.01;
    model.seed = 7;
    model.max_range = params.max_range;
    OffRoadRun r{{}, pose};
    r.run.scan = sim::scan(scene, model, pose);
    FrameInput input;
    input.vehicle_attitude = pose.linear();
    Pipeline pipeline(params);
    pipeline.process(r.run.scan.cloud, input, r.run.result);
    r.run.scores = test::scoreScene(r.run.scan.gt, r.run.result.labels);
    return r;
}

// The errors of an off-road run by cause: non-ground taken as ground by object group (and steep
// terrain), ground missed by where it lies (a named region of the scene, or the grass canopy:
// 3 cm or more above the soil), and the mirrored returns by label.
struct OffRoadCauses {
    std::map<std::string, std::size_t> as_ground, missed;
    std::size_t reflections = 0, reflections_as_ground = 0;
};

template <typename GroupOf, typename RegionOf>
OffRoadCauses offRoadCauses(const OffRoadRun& r, GroupOf groupOf, RegionOf regionOf) {
    OffRoadCauses c;
    const sim::GroundTruth& gt = r.run.scan.gt;
    const PointCloud& cloud = r.run.scan.cloud;
    for (std::size_t i = 0; i < gt.size(); ++i) {
        const bool as_ground = r.run.result.labels[i] == PointClass::Ground;
        if (gt.cls[i] == sim::Reflection) {
            ++c.reflections;
            c.reflections_as_ground += as_ground;
            continue;
        }
        const Eigen::Vector3d p = r.pose * Eigen::Vector3d(cloud.x[i], cloud.y[i], cloud.z[i]);
        const double range = p.head<2>().norm();
        const char* bin = range < 10 ? " 0-10" : range < 20 ? " 10-20" : " 20+";
        if (gt.cls[i] == sim::NonGround && as_ground)
            ++c.as_ground[(gt.instance[i] ? groupOf(gt.instance[i]) : std::string("steep")) + bin];
        if (gt.cls[i] == sim::Ground && !as_ground)
            ++c.missed[(gt.height_above_ground[i] >= 0.03f ? std::string("canopy")
                                                           : std::string(regionOf(p))) +
                       (r.run.result.labels[i] == PointClass::Outlier ? "/outlier" : "") + bin];
    }
    return c;
}

void print(const char* name, const OffRoadRun& r, const OffRoadCauses& c) {
    print(name, r.run.scores);
    std::printf("  as ground:");
    for (const auto& [k, v] : c.as_ground) std::printf(" %s %zu;", k.c_str(), v);
    std::printf("\n  missed:");
    for (const auto& [k, v] : c.missed) std::printf(" %s %zu;", k.c_str(), v);
    std::printf("\n  mirrored returns %zu, as ground %zu\n", c.reflections,
                c.reflections_as_ground);
}

std::string meadowGroup(uint32_t id) {
    return id <= 8 ? "bush" : id <= 16 ? "trunk" : id <= 26 ? "shrub" : id <= 38 ? "rock" : "?";
}
std::string soil(const Eigen::Vector3d&) {
    return "soil";
}
std::size_t sumOf(const std::map<std::string, std::size_t>& counts, const std::string& prefix) {
    std::size_t sum = 0;
    for (const auto& [key, count] : counts) sum += key.rfind(prefix, 0) == 0 ? count : 0;
    return sum;
}

// Grass 0.12-0.5 m (ground), bushes, trunks, low shrubs and rocks on the uneven meadow; the
// OS1-64 level and pitched 6 deg down on its mount (the attitude given). Measured (level /
// pitched): precision 0.9913 / 0.9911, recall 0.9547 / 0.9334. Not fixed: the canopy of the
// tall grass 0.13 m or more above the plane is non-ground by eq. 5 (1,434 / 1,443 points 0-10 m,
// 2,445 / 2,782 in all); the grass raises the node planes, so that rocks up to 0.35 m and low
// shrubs up to 0.5 m lie within eps3 of them (rock points as ground 262 / 266, shrub 156 / 153);
// the face rule needs a non-ground face 0.25 m above the foot (kerbs) and finds none there.
// Pitched, the soil 20 m and farther is missed (897 points; 35 level).
void tallGrassShrubsAndRocks(double mount_pitch_deg, double min_precision, double min_recall,
                             std::size_t max_rocks_and_shrubs, std::size_t max_bushes_and_trunks) {
    const sim::Scene scene = sim::offRoadTallGrassAndRocks();
    const OffRoadRun r = segmentOffRoad(
        scene, vehicleSensorPose(scene, 0.0, mount_pitch_deg, sim::kOffRoadSensorHeight));
    const OffRoadCauses c = offRoadCauses(r, meadowGroup, soil);
    std::printf("tall_grass_pitch%.0f", mount_pitch_deg);
    print("", r, c);
    EXPECT_GE(r.run.scores.precision(), min_precision);
    EXPECT_GE(r.run.scores.recall(), min_recall);
    EXPECT_LE(sumOf(c.as_ground, "rock") + sumOf(c.as_ground, "shrub"), max_rocks_and_shrubs);
    EXPECT_LE(sumOf(c.as_ground, "bush") + sumOf(c.as_ground, "trunk"), max_bushes_and_trunks);
    EXPECT_LE(r.run.scores.high_obstacle_as_ground, 25u);
}

TEST(HardScenes, OffRoadTallGrassShrubsAndRocks) {
    tallGrassShrubsAndRocks(0.0, 0.989, 0.950, 480, 70);
}

TEST(HardScenes, OffRoadTallGrassShrubsAndRocksPitchedMount) {
    tallGrassShrubsAndRocks(6.0, 0.989, 0.928, 480, 70);
}

// Farm fences (posts every 3 m, four wires 1.5 cm thick from 0.2 m up) across 0.15 m grass.
// Measured: precision 0.9998, recall 0.9756 (the canopy: 1,398 of the 1,450 missed points),
// post points as ground 4, wire 8.
TEST(HardScenes, OffRoadFenceLinesInGrass) {
    const sim::Scene scene = sim::offRoadFenceLines();
    const OffRoadRun r =
        segmentOffRoad(scene, vehicleSensorPose(scene, 0.0, 0.0, sim::kOffRoadSensorHeight));
    const OffRoadCauses c = offRoadCauses(
        r, [](uint32_t id) { return id <= 45 ? std::string("post") : std::string("wire"); }, soil);
    print("fence_lines", r, c);
    EXPECT_GE(r.run.scores.precision(), 0.999);
    EXPECT_GE(r.run.scores.f1(), 0.985);
    EXPECT_LE(sumOf(c.as_ground, "post") + sumOf(c.as_ground, "wire"), 25u);
}

// A track with ruts and puddles between ditches 0.6 m (20 deg sides) and 0.4 m deep (15 deg),
// grass beside it. The nodes at a ditch's bottom are reached and fit its bottom, but TTMF's
// corners average their planes with the track's and the field's (eq. 1), which lifts them
// 0.3-0.6 m: without onOwnPlaneOnly's lower side (GroundLabelling.cpp) the bottom lies more than
// outlier_dist below the refitted plane: outliers (left ditch 868 points, right 35; recall
// 0.9400, F1 0.9689). With it: outliers 4 and 1, recall 0.9585, F1 0.9787, precision 0.9998
// either way. Not fixed: the canopy (2,194 missed), the mirrored returns of the water that lie
// within 0.3 m below it (5 of 5 labelled ground; not scored: SemanticKITTI's outliers).
TEST(HardScenes, OffRoadTrackWithDitchesRutsAndPuddles) {
    const sim::Scene scene = sim::offRoadTrackWithDitchesRutsAndPuddles();
    const OffRoadRun r =
        segmentOffRoad(scene, vehicleSensorPose(scene, 0.0, 0.0, sim::kOffRoadSensorHeight));
    const auto region = [&](const Eigen::Vector3d& p) {
        for (const sim::Puddle& puddle : scene.puddles)
            if ((p.head<2>() - puddle.centre).norm() < puddle.radius + 0.5) return "puddle";
        const double y = p.y();
        if (y > 3.4 && y < 7.7) return "ditch_left";
        if (y < -3.4 && y > -7.2) return "ditch_right";
        if (std::abs(y) > 0.55 && std::abs(y) < 1.0) return "rut";
        return std::abs(y) < 3.4 ? "track" : "field";
    };
    const OffRoadCauses c = offRoadCauses(
        r, [](uint32_t id) { return id <= 3 ? std::string("bush") : std::string("trunk"); },
        region);
    print("track_ditch_ruts_puddles", r, c);
    std::size_t ditch_outliers = 0;
    for (const auto& [key, count] : c.missed)
        ditch_outliers +=
            key.rfind("ditch", 0) == 0 && key.find("/outlier") != std::string::npos ? count : 0;
    EXPECT_LE(ditch_outliers, 20u);
    EXPECT_GE(r.run.scores.recall(), 0.955);
    EXPECT_GE(r.run.scores.precision(), 0.999);
    EXPECT_LE(sumOf(c.as_ground, "bush") + sumOf(c.as_ground, "trunk"), 25u);
    EXPECT_GT(c.reflections, 0u);
    EXPECT_LE(c.reflections_as_ground, 10u);
}

// The vehicle on a 20 deg grassy hillside with bushes, trunks and rocks, facing up the slope
// and across it (the attitude given). Measured (up / across): precision 0.9945 / 0.9934,
// recall 0.9529 / 0.9734 (without onOwnPlaneOnly's lower side 0.9507 / 0.9718: the bottoms of
// hollows between the bumps, below their lifted refitted planes, are outliers); rock points as
// ground 257 / 324, bush and trunk 58 / 66; the misses are the canopy (1,771 / 1,080) and soil
// 20 m and farther (853 / 349).
void twentyDegreeHillside(double yaw_deg) {
    const sim::Scene scene = sim::offRoadHillside(20.0);
    const OffRoadRun r =
        segmentOffRoad(scene, vehicleSensorPose(scene, yaw_deg, 0.0, sim::kOffRoadSensorHeight));
    const OffRoadCauses c = offRoadCauses(r, meadowGroup, soil);
    std::printf("hillside20_yaw%.0f", yaw_deg);
    print("", r, c);
    EXPECT_GE(r.run.scores.precision(), 0.992);
    EXPECT_GE(r.run.scores.recall(), 0.948);
    EXPECT_LE(sumOf(c.as_ground, "rock"), 400u);
    EXPECT_LE(sumOf(c.as_ground, "bush") + sumOf(c.as_ground, "trunk"), 90u);
    EXPECT_LE(r.run.scores.high_obstacle_as_ground, 35u);
}

TEST(HardScenes, OffRoadTwentyDegreeHillsideUpTheSlope) {
    twentyDegreeHillside(0.0);
}

TEST(HardScenes, OffRoadTwentyDegreeHillsideAcrossTheSlope) {
    twentyDegreeHillside(90.0);
}

TEST(HardScenes, CarTwoMetresFromA64And128BeamSensor) {
    struct Sensor {
        const char* name;
        sim::LidarModel model;
        Params params;
    };
    Params p64 = hdl64Params();
    p64.min_range = 1.0;  // the car is nearer than KITTI's 2.7 m self-return cut
    Params p128 = p64;
    p128.num_rings = 128;
    p128.num_columns = 1024;
    p128.elevation_table = "os128";
    for (const Sensor& s : {Sensor{"hdl64", sim::LidarModel::hdl64(), p64},
                            Sensor{"os128", sim::LidarModel::os128(), p128}}) {
        const SceneRun run =
            segment(sim::carBesideSensor(2.0), s.model, s.params, sim::kSensorHeight);
        const test::ObjectScore car =
            test::scoreObject(run.scan.gt, run.result.labels, run.result.cluster_id, 1);
        std::printf("car_2m_%-21s coverage %.3f purity %.3f (%zu points)\n", s.name, car.coverage,
                    car.purity, car.points);
        SCOPED_TRACE(s.name);
        // A box car does not reproduce the split seen on real data (windows, dark paint):
        // this holds the level of the ideal case only.
        EXPECT_GE(car.coverage, 0.9);
        EXPECT_GE(car.purity, 0.99);
    }
}

}  // namespace
}  // namespace travel
